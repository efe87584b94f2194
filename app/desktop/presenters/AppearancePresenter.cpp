#include "app/desktop/presenters/AppearancePresenter.h"

#include "app/desktop/presenters/CanvasPresenter.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMenu>
#include <QSettings>
#include <QStyle>

#include <algorithm>
#include <cmath>

namespace phasebox {

namespace {
double clampScale(double scale) {
    if (!std::isfinite(scale)) return 1.0;
    return std::clamp(scale, ui::kMinAppearanceScale, ui::kMaxAppearanceScale);
}
}  // namespace

AppearancePresenter::AppearancePresenter(CanvasPresenter& canvas, QObject* parent)
    : Presenter(parent), canvas_(canvas) {}

void AppearancePresenter::refresh() {}

void AppearancePresenter::createActions(QWidget& window) {
    highContrast_ = addWindowAction(window, QStringLiteral("highContrast"), tr("High &Contrast"),
                                    QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_H));
    highContrast_->setCheckable(true);
    highContrast_->setToolTip(
        tr("White on black, with a yellow selection and focus: for a "
           "projector or for low vision"));
    connect(highContrast_, &QAction::toggled, this, [this](bool on) {
        ui::Appearance a = appearance_;
        a.highContrast = on;
        setAppearance(a);
    });
    const auto makeGroup = [&](const char* prefix, QList<QAction*>& actions,
                               double ui::Appearance::*member) {
        auto* group = new QActionGroup(this);
        for (const double scale : ui::kAppearanceScales) {
            const int percent = static_cast<int>(std::lround(scale * 100.0));
            QAction* a = addWindowAction(
                window, QStringLiteral("%1%2").arg(QLatin1String(prefix)).arg(percent),
                tr("%1 %").arg(percent));
            a->setCheckable(true);
            a->setData(scale);
            group->addAction(a);
            actions << a;
            connect(a, &QAction::triggered, this, [this, member, scale] {
                ui::Appearance next = appearance_;
                next.*member = scale;
                setAppearance(next);
            });
        }
    };
    makeGroup("lineScale", lineScales_, &ui::Appearance::lineScale);
    makeGroup("textScale", textScales_, &ui::Appearance::textScale);
    syncActions();
}

void AppearancePresenter::addToMenu(QMenu& view) {
    view.addAction(highContrast_);
    QMenu* lines = view.addMenu(tr("Line &Width"));
    lines->setObjectName(QStringLiteral("lineScaleMenu"));
    lines->addActions(lineScales_);
    QMenu* text = view.addMenu(tr("Te&xt Size"));
    text->setObjectName(QStringLiteral("textScaleMenu"));
    text->addActions(textScales_);
}

void AppearancePresenter::setAppearance(const ui::Appearance& appearance) {
    ui::Appearance next = appearance;
    next.lineScale = clampScale(next.lineScale);
    next.textScale = clampScale(next.textScale);
    const bool themeChanged = next.highContrast != appearance_.highContrast;
    appearance_ = next;
    if (themeChanged)
        QApplication::setPalette(next.highContrast ? ui::highContrastPalette()
                                                   : QApplication::style()->standardPalette());
    ui::setChartAppearance(next);
    canvas_.setAppearance(next);
    syncActions();
    emit changed();
}

void AppearancePresenter::syncActions() {
    if (highContrast_) {
        const QSignalBlocker block(highContrast_);
        highContrast_->setChecked(appearance_.highContrast);
    }
    for (QAction* a : std::as_const(lineScales_))
        a->setChecked(std::abs(a->data().toDouble() - appearance_.lineScale) < 1e-9);
    for (QAction* a : std::as_const(textScales_))
        a->setChecked(std::abs(a->data().toDouble() - appearance_.textScale) < 1e-9);
}

void AppearancePresenter::readSettings(const QSettings& settings) {
    ui::Appearance a;
    a.highContrast = settings.value(QStringLiteral("view/highContrast"), false).toBool();
    // A damaged or hand-edited number falls back to 1 (setAppearance clamps the rest).
    for (const auto& [key, value] :
         {std::pair{"view/lineScale", &a.lineScale}, std::pair{"view/textScale", &a.textScale}}) {
        bool ok = false;
        const double read = settings.value(QLatin1String(key), 1.0).toDouble(&ok);
        *value = ok && std::isfinite(read) ? read : 1.0;
    }
    setAppearance(a);
}

void AppearancePresenter::writeSettings(QSettings& settings) const {
    settings.setValue(QStringLiteral("view/highContrast"), appearance_.highContrast);
    settings.setValue(QStringLiteral("view/lineScale"), appearance_.lineScale);
    settings.setValue(QStringLiteral("view/textScale"), appearance_.textScale);
}

}  // namespace phasebox
