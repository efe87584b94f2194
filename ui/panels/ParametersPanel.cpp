#include "ui/panels/ParametersPanel.h"

#include "physics/integrators/Integrator.h"
#include "physics/scene/SceneSchema.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/PropertiesPanel.h"  // ScientificSpinBox
#include "ui/panels/ShownNumber.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace phasebox::ui {

namespace {
// The editors' limits of a simulation setting: its schema field's (schema::Editor).
const schema::Editor& limits(std::string_view key) {
    return schema::simulationField(key).editor;
}

QString qs(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// A contact model's name in the app's language (CONTRACT §6 keeps the file's names English).
QString contactModelText(std::size_t index, const QString& name) {
    const QString shown[] = {ParametersPanel::tr("Impulse"), ParametersPanel::tr("Penalty"),
                             ParametersPanel::tr("Kinematic")};
    return index < std::size(shown) ? shown[index] : name.left(1).toUpper() + name.mid(1);
}

QString integratorToolTip(const IntegratorInfo& info) {
    const QString kind =
        info.implicit ? ParametersPanel::tr("implicit") : ParametersPanel::tr("explicit");
    const QString symplectic =
        info.symplectic ? ParametersPanel::tr("symplectic") : ParametersPanel::tr("not symplectic");
    QString facts = ParametersPanel::tr("order %1 · %2 · %3").arg(info.order).arg(kind, symplectic);
    if (info.adaptive) facts += ParametersPanel::tr(" · adaptive step");
    return ParametersPanel::tr("%1 (%2)\n%3\nforce evaluations per step: %4\n%5")
        .arg(integratorText(info.label), qs(info.name), facts, integratorText(info.evaluations),
             integratorText(info.summary));
}

// "1/60 s", or the number itself when it is not the reciprocal of a whole number.
QString presetLabel(double seconds) {
    const double per = 1.0 / seconds;
    if (std::abs(per - std::round(per)) < 1e-9)
        return ParametersPanel::tr("1/%1 s  (%2 s)")
            .arg(std::lround(per))
            .arg(shownNumber(seconds, 'g', 3));
    return ParametersPanel::tr("%1 s").arg(shownNumber(seconds));
}
}  // namespace

const std::vector<double>& ParametersPanel::dtPresets() {
    static const std::vector<double> presets{1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 1000};
    return presets;
}

const std::vector<double>& ParametersPanel::speeds() {
    static const std::vector<double> factors{0.25, 0.5, 1.0, 2.0, 4.0};
    return factors;
}

ParametersPanel::ParametersPanel(QWidget* parent) : QWidget(parent) {
    // ---- transport: the app's actions drive these (setActions) --------------------------
    auto makeButton = [this](const char* name, const QString& text, const QString& tip) {
        auto* button = new QToolButton;
        button->setObjectName(QLatin1String(name));
        button->setText(text);
        button->setToolTip(tip);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        button->setFocusPolicy(Qt::StrongFocus);
        button->setEnabled(false);  // nothing to do until the app hands over its action
        return button;
    };
    playButton_ = makeButton("play", tr("Play"), tr("Play or pause (Space)"));
    stepButton_ = makeButton("step", tr("Step"), tr("Advance one step (S or Right)"));
    resetButton_ = makeButton("reset", tr("Reset"), tr("Back to the scene's setup (R or Ctrl+R)"));
    auto* transport = new QHBoxLayout;
    transport->setSpacing(4);
    transport->addWidget(playButton_);
    transport->addWidget(stepButton_);
    transport->addWidget(resetButton_);

    // ---- integrator ----------------------------------------------------------------------
    integratorBox_ = new QComboBox;
    integratorBox_->setObjectName(QStringLiteral("integrator"));
    // Long labels ("Adaptive Euler (step doubling)") must not force the dock wider.
    integratorBox_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    integratorBox_->setMinimumContentsLength(14);
    for (const IntegratorInfo& info : integratorRegistry()) {
        integratorBox_->addItem(integratorText(info.label), qs(info.name));
        integratorBox_->setItemData(integratorBox_->count() - 1, integratorToolTip(info),
                                    Qt::ToolTipRole);
    }
    connect(integratorBox_, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabledFields();
        emit integratorChanged(integrator());
    });

    // ---- dt and its presets --------------------------------------------------------------
    dtBox_ = new ScientificSpinBox;
    dtBox_->setObjectName(QStringLiteral("dt"));
    const schema::Editor& dt = limits(schema::key::dt);
    dtBox_->setRange(dt.min, dt.max);
    dtBox_->setSignificantDigits(4);
    // Halving dt is the classroom experiment (order of accuracy), so the arrows halve and
    // double rather than add a fixed amount that is too big at 1e-4 and too small at 0.1.
    dtBox_->setStepFactor(2.0);
    dtBox_->setSuffix(tr(" s"));
    dtBox_->setToolTip(tr("The frame step: the time one step advances (%1 … %2 s).\n"
                          "The arrows halve or double it; 2e-4 style entry is accepted.")
                           .arg(dtBox_->formatNumber(dt.min), dtBox_->formatNumber(dt.max)));
    connect(dtBox_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::dtChanged);

    dtPresetButton_ = new QToolButton;
    dtPresetButton_->setObjectName(QStringLiteral("dtPresets"));
    dtPresetButton_->setText(tr("1/n"));
    dtPresetButton_->setToolTip(tr("Common frame steps"));
    dtPresetButton_->setAccessibleName(tr("dt presets"));
    dtPresetButton_->setPopupMode(QToolButton::InstantPopup);
    dtPresetButton_->setFocusPolicy(Qt::StrongFocus);
    auto* presetMenu = new QMenu(dtPresetButton_);
    for (double preset : dtPresets())
        presetMenu->addAction(presetLabel(preset), this,
                              [this, preset] { dtBox_->setValue(preset); });
    dtPresetButton_->setMenu(presetMenu);
    auto* dtRow = new QHBoxLayout;
    dtRow->setSpacing(2);
    dtRow->addWidget(dtBox_, 1);
    dtRow->addWidget(dtPresetButton_);

    // ---- sub-steps, tolerance, Newton ----------------------------------------------------
    substepsBox_ = new QSpinBox;
    substepsBox_->setObjectName(QStringLiteral("substeps"));
    const schema::Editor& substeps = limits(schema::key::substeps);
    substepsBox_->setRange(static_cast<int>(substeps.min), static_cast<int>(substeps.max));
    substepsBox_->setKeyboardTracking(false);
    substepsBox_->setAccelerated(true);
    substepsBox_->setToolTip(tr("Each step is split into this many equal sub-steps"));
    connect(substepsBox_, &QSpinBox::valueChanged, this, &ParametersPanel::substepsChanged);

    QStringList adaptiveNames;
    for (const IntegratorInfo& info : integratorRegistry())
        if (info.adaptive) adaptiveNames << qs(info.name);
    toleranceBox_ = new ScientificSpinBox;
    toleranceBox_->setObjectName(QStringLiteral("tolerance"));
    const schema::Editor& tolerance = limits(schema::key::tolerance);
    toleranceBox_->setRange(tolerance.min, tolerance.max);
    toleranceBox_->setSignificantDigits(3);
    toleranceBox_->setStepFactor(10.0);  // tolerances are chosen by decade
    toleranceBox_->setToolTip(tr("Local error tolerance of the adaptive methods (%1);\n"
                                 "the arrows move it by a factor of ten")
                                  .arg(adaptiveNames.join(QStringLiteral(", "))));
    connect(toleranceBox_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::toleranceChanged);

    newtonBox_ = new QSpinBox;
    newtonBox_->setObjectName(QStringLiteral("newtonIterations"));
    const schema::Editor& newton = limits(schema::key::newtonIterations);
    newtonBox_->setRange(static_cast<int>(newton.min), static_cast<int>(newton.max));
    newtonBox_->setKeyboardTracking(false);
    newtonBox_->setToolTip(
        tr("Newton iterations of implicit Euler per step\n"
           "(1 = the linearised step of Baraff & Witkin)"));
    connect(newtonBox_, &QSpinBox::valueChanged, this, &ParametersPanel::newtonIterationsChanged);

    // ---- contact model (CONTRACT §6), switched live like the integrator -----------------
    contactModelBox_ = new QComboBox;
    contactModelBox_->setObjectName(QStringLiteral("contactModel"));
    const QStringList modelTips{
        tr("Impulses after the step, with friction and restitution: stacks rest"),
        tr("A stiff damped spring in each overlap, F = k·d + c·ḋ: a smooth force the integrator "
           "sees, with its potential ½·k·d² in the energy"),
        tr("Move the bodies apart and reflect the approaching velocity by e; no forces")};
    for (std::size_t i = 0; i < kContactModelNames.size(); ++i) {
        const QString name = QString::fromLatin1(
            kContactModelNames[i].data(), static_cast<qsizetype>(kContactModelNames[i].size()));
        contactModelBox_->addItem(contactModelText(i, name), name);
        contactModelBox_->setItemData(static_cast<int>(i), modelTips.at(static_cast<qsizetype>(i)),
                                      Qt::ToolTipRole);
    }
    connect(contactModelBox_, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabledFields();
        emit contactModelChanged(contactModel());
    });
    stiffnessBox_ = new ScientificSpinBox;
    stiffnessBox_->setObjectName(QStringLiteral("contactStiffness"));
    const schema::Editor& stiffness = limits(schema::key::contactStiffness);
    stiffnessBox_->setRange(stiffness.min, stiffness.max);
    stiffnessBox_->setSignificantDigits(3);
    stiffnessBox_->setStepFactor(10.0);
    stiffnessBox_->setSuffix(tr(" N/m"));
    // Shown at the minimum: the automatic stiffness of a scene with nothing that moves.
    stiffnessBox_->setSpecialValueText(tr("none yet"));
    stiffnessBox_->setToolTip(
        tr("Penalty stiffness k per contact point; the arrows move it by a "
           "factor of ten"));
    connect(stiffnessBox_, &QDoubleSpinBox::valueChanged, this,
            &ParametersPanel::contactStiffnessChanged);
    automaticStiffnessButton_ = new QToolButton;
    automaticStiffnessButton_->setObjectName(QStringLiteral("automaticStiffness"));
    automaticStiffnessButton_->setText(tr("Auto"));
    automaticStiffnessButton_->setCheckable(true);
    automaticStiffnessButton_->setToolTip(
        tr("Automatic stiffness: the lightest body gets ω·h = 0.5 at the step"));
    connect(automaticStiffnessButton_, &QToolButton::clicked, this, [this](bool automatic) {
        emit contactStiffnessChanged(automatic ? 0.0 : stiffnessBox_->value());
    });
    auto* stiffnessRow = new QHBoxLayout;
    stiffnessRow->setSpacing(2);
    stiffnessRow->addWidget(stiffnessBox_, 1);
    stiffnessRow->addWidget(automaticStiffnessButton_);
    contactDampingBox_ = new ScientificSpinBox;
    contactDampingBox_->setObjectName(QStringLiteral("contactDamping"));
    const schema::Editor& damping = limits(schema::key::contactDamping);
    contactDampingBox_->setRange(damping.min, damping.max);
    contactDampingBox_->setSignificantDigits(3);
    contactDampingBox_->setSuffix(tr(" N·s/m"));
    contactDampingBox_->setToolTip(tr("Penalty damping c per contact point"));
    connect(contactDampingBox_, &QDoubleSpinBox::valueChanged, this,
            &ParametersPanel::contactDampingChanged);

    // ---- speed ---------------------------------------------------------------------------
    speedBox_ = new QComboBox;
    speedBox_->setObjectName(QStringLiteral("speed"));
    const QStringList speedLabels{QStringLiteral("¼×"), QStringLiteral("½×"), QStringLiteral("1×"),
                                  QStringLiteral("2×"), QStringLiteral("4×")};
    for (std::size_t i = 0; i < speeds().size(); ++i)
        speedBox_->addItem(speedLabels.at(static_cast<qsizetype>(i)), speeds()[i]);
    speedBox_->setCurrentIndex(2);
    speedBox_->setToolTip(tr("Simulated seconds per second of wall time (slow motion below 1×)"));
    connect(speedBox_, &QComboBox::currentIndexChanged, this,
            [this] { emit speedChanged(speed()); });

    sleepBox_ = new QCheckBox(tr("Let resting &bodies sleep"));
    sleepBox_->setObjectName(QStringLiteral("sleep"));
    sleepBox_->setToolTip(
        tr("Bodies that have stayed at rest for half a second are no longer simulated, and are "
           "drawn dimmed, until something touches them, drags them or an edit wakes them: "
           "large resting piles cost almost nothing"));
    connect(sleepBox_, &QCheckBox::toggled, this, &ParametersPanel::sleepChanged);

    // ---- form ----------------------------------------------------------------------------
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // Rows a little closer than the style's spacing: the lower tabs (Properties) keep their
    // height with the sleep switch's row added.
    form->setVerticalSpacing(std::max(0, form->verticalSpacing() - 2));
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    auto addRow = [form](const QString& text, QWidget* field, QLayout* fieldLayout = nullptr) {
        auto* label = new QLabel(text);
        label->setBuddy(field);
        if (fieldLayout)
            form->addRow(label, fieldLayout);
        else
            form->addRow(label, field);
        return label;
    };
    addRow(tr("&Integrator:"), integratorBox_);
    addRow(tr("&dt:"), dtBox_, dtRow);
    addRow(tr("S&ub-steps:"), substepsBox_);
    toleranceLabel_ = addRow(tr("&Tolerance:"), toleranceBox_);
    newtonLabel_ = addRow(tr("&Newton iter.:"), newtonBox_);
    newtonLabel_->setToolTip(tr("Newton iterations (implicit Euler only)"));
    addRow(tr("&Contacts:"), contactModelBox_);
    stiffnessLabel_ = addRow(tr("Sti&ffness:"), stiffnessBox_, stiffnessRow);
    contactDampingLabel_ = addRow(tr("Dam&ping:"), contactDampingBox_);
    form->addRow(sleepBox_);  // across both columns: the label is the box's own text
    addRow(tr("Sp&eed:"), speedBox_);

    // ---- stability advisor ---------------------------------------------------------------
    advice_ = new QLabel;
    advice_->setObjectName(QStringLiteral("advice"));
    advice_->setWordWrap(true);
    advice_->setTextFormat(Qt::PlainText);
    advice_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    advice_->hide();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addLayout(transport);
    layout->addLayout(form);
    layout->addWidget(advice_);
    layout->addStretch(1);

    // A number typed out of range is refused and the field goes back; say why next to it.
    for (auto [box, name] :
         {std::pair{dtBox_, tr("dt")}, std::pair{toleranceBox_, tr("tolerance")}})
        connect(box, &ScientificSpinBox::inputRejected, box, [box, name](const QString& reason) {
            QToolTip::showText(box->mapToGlobal(QPoint(0, box->height())),
                               QStringLiteral("%1 %2").arg(name, reason), box);
        });
    // Scrolling the dock's neighbourhood with the wheel must not switch the integrator or dt
    // mid-run: a setting takes the wheel only once it has the focus (click or Tab).
    for (QWidget* field : std::initializer_list<QWidget*>{
             integratorBox_, dtBox_, substepsBox_, toleranceBox_, newtonBox_, contactModelBox_,
             stiffnessBox_, contactDampingBox_, speedBox_}) {
        field->setFocusPolicy(Qt::StrongFocus);
        field->installEventFilter(this);
    }

    setTabOrder(playButton_, stepButton_);
    setTabOrder(stepButton_, resetButton_);
    setTabOrder(resetButton_, integratorBox_);
    setTabOrder(integratorBox_, dtBox_);
    setTabOrder(dtBox_, dtPresetButton_);
    setTabOrder(dtPresetButton_, substepsBox_);
    setTabOrder(substepsBox_, toleranceBox_);
    setTabOrder(toleranceBox_, newtonBox_);
    setTabOrder(newtonBox_, contactModelBox_);
    setTabOrder(contactModelBox_, stiffnessBox_);
    setTabOrder(stiffnessBox_, automaticStiffnessButton_);
    setTabOrder(automaticStiffnessButton_, contactDampingBox_);
    setTabOrder(contactDampingBox_, sleepBox_);
    setTabOrder(sleepBox_, speedBox_);

    setMinimumWidth(240);
    setSimulation(SimulationDesc{});
}

void ParametersPanel::setSimulation(const SimulationDesc& simulation) {
    const QSignalBlocker blockIntegrator(integratorBox_);
    const QSignalBlocker blockDt(dtBox_);
    const QSignalBlocker blockSubsteps(substepsBox_);
    const QSignalBlocker blockTolerance(toleranceBox_);
    const QSignalBlocker blockNewton(newtonBox_);
    const QSignalBlocker blockModel(contactModelBox_);
    const QSignalBlocker blockDamping(contactDampingBox_);
    const QSignalBlocker blockSleep(sleepBox_);

    const int index = integratorBox_->findData(QString::fromStdString(simulation.integrator));
    if (index >= 0) integratorBox_->setCurrentIndex(index);
    // A valid scene may lie outside the editors' everyday ranges (dt 1e-6, 5000 sub-steps):
    // widen the range rather than show a number that is not the scene's.
    if (simulation.dt > 0.0)
        dtBox_->setMinimum(std::min(limits(schema::key::dt).min, simulation.dt));
    dtBox_->setValue(simulation.dt);
    substepsBox_->setMaximum(
        std::max(static_cast<int>(limits(schema::key::substeps).max), simulation.substeps));
    substepsBox_->setValue(simulation.substeps);
    if (simulation.tolerance > 0.0)
        toleranceBox_->setMinimum(
            std::min(limits(schema::key::tolerance).min, simulation.tolerance));
    toleranceBox_->setValue(simulation.tolerance);
    newtonBox_->setValue(simulation.newtonIterations);
    contactModelBox_->setCurrentIndex(static_cast<int>(simulation.contactModel));
    contactDampingBox_->setValue(simulation.contactDamping);
    sleepBox_->setChecked(simulation.sleep);
    if (simulation.contactStiffness) setContactStiffness(*simulation.contactStiffness, false);
    updateEnabledFields();
}

void ParametersPanel::setContactStiffness(double stiffness, bool automatic) {
    const QSignalBlocker blockStiffness(stiffnessBox_);
    const QSignalBlocker blockAutomatic(automaticStiffnessButton_);
    // No body to set it by (a new scene): no figure, rather than the last scene's.
    stiffnessBox_->setValue(stiffness > 0.0 ? stiffness : stiffnessBox_->minimum());
    automaticStiffnessButton_->setChecked(automatic);
}

ContactModel ParametersPanel::contactModel() const {
    return static_cast<ContactModel>(std::max(0, contactModelBox_->currentIndex()));
}

void ParametersPanel::setSpeed(double factor) {
    // Nearest on a log scale: 3× is closer to 4× than to 2× in the way slow motion feels.
    int best = 0;
    double bestDistance = HUGE_VAL;
    for (std::size_t i = 0; i < speeds().size(); ++i) {
        const double distance = std::abs(std::log(std::max(factor, 1e-9) / speeds()[i]));
        if (distance < bestDistance) bestDistance = distance, best = static_cast<int>(i);
    }
    const QSignalBlocker blocker(speedBox_);
    speedBox_->setCurrentIndex(best);
}

bool ParametersPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Wheel) {
        const auto* field = qobject_cast<QWidget*>(watched);
        if (field && !field->hasFocus()) {
            event->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ParametersPanel::updateEnabledFields() {
    const QString name = integrator();
    const IntegratorInfo* info = findIntegrator(name.toStdString());
    const bool adaptive = info && info->adaptive;
    const bool newton = info && info->usesNewtonIterations;
    toleranceBox_->setEnabled(adaptive);
    toleranceLabel_->setEnabled(adaptive);
    newtonBox_->setEnabled(newton);
    newtonLabel_->setEnabled(newton);
    integratorBox_->setToolTip(integratorBox_->currentData(Qt::ToolTipRole).toString());
    const bool penalty = contactModel() == ContactModel::Penalty;
    for (QWidget* w :
         std::initializer_list<QWidget*>{stiffnessBox_, automaticStiffnessButton_, stiffnessLabel_,
                                         contactDampingBox_, contactDampingLabel_})
        w->setEnabled(penalty);
    contactModelBox_->setToolTip(contactModelBox_->currentData(Qt::ToolTipRole).toString());
}

void ParametersPanel::setButtonAction(QToolButton* button, QAction* action) {
    if (QAction* old = button->defaultAction()) {
        disconnect(old, nullptr, button, nullptr);
        button->removeAction(old);
    }
    if (!action) {
        button->setEnabled(false);
        return;
    }
    button->setDefaultAction(action);
    // QToolButton copies the action's tooltip on every change (Play → Pause); add the
    // shortcuts after it, so the tooltip always teaches the keys.
    auto updateToolTip = [button, action] {
        QString tip = action->toolTip();
        QStringList keys;
        for (const QKeySequence& key : action->shortcuts())
            keys << key.toString(QKeySequence::NativeText);
        const QString shortcut = QStringLiteral("(%1)").arg(keys.join(tr(" or ")));
        if (!keys.isEmpty() && !tip.contains(shortcut)) tip += QLatin1Char(' ') + shortcut;
        button->setToolTip(tip);
    };
    updateToolTip();
    connect(action, &QAction::changed, button, updateToolTip);
}

void ParametersPanel::setActions(QAction* play, QAction* step, QAction* reset) {
    setButtonAction(playButton_, play);
    setButtonAction(stepButton_, step);
    setButtonAction(resetButton_, reset);
}

void ParametersPanel::setAdvice(const QString& text, bool warning, const QString& details) {
    advice_->setToolTip(details);
    // The sign as well as the colour: a warning must not depend on telling red from green.
    advice_->setText(warning ? QStringLiteral("⚠ ") + text : text);
    advice_->setProperty("warning", warning);
    advice_->setStyleSheet(
        warning ? QStringLiteral("QLabel { color: #8e1b12; background: #fdecea; "
                                 "border: 1px solid #e57373; border-radius: 3px; padding: 4px; }")
                : QStringLiteral("QLabel { color: #1b5e20; background: #edf7ed; "
                                 "border: 1px solid #a5d6a7; border-radius: 3px; padding: 4px; }"));
    advice_->setVisible(!text.isEmpty());
}

QString ParametersPanel::integrator() const {
    return integratorBox_->currentData().toString();
}
double ParametersPanel::dt() const {
    return dtBox_->value();
}
int ParametersPanel::substeps() const {
    return substepsBox_->value();
}
double ParametersPanel::tolerance() const {
    return toleranceBox_->value();
}
int ParametersPanel::newtonIterations() const {
    return newtonBox_->value();
}
double ParametersPanel::speed() const {
    return speedBox_->currentData().toDouble();
}
QString ParametersPanel::adviceText() const {
    return advice_->text();
}

}  // namespace phasebox::ui
