#include "app/desktop/AccuracyDialog.h"

#include "app/accuracy/OrderAssessment.h"
#include "app/document/Document.h"

#include "app/io/ChartFile.h"
#include "app/io/NumberFormat.h"
#include "app/io/OutputFile.h"
#include "app/io/SceneIO.h"
#include "physics/integrators/Integrator.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/ShownNumber.h"
#include "ui/plots/Charts.h"
#include "ui/plots/WorkPrecisionChart.h"

#include <QChart>
#include <QChartView>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextStream>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace phasebox {

namespace {
// The window's numbers in its locale; the CSV export writes its own, '.'-decimal.
QString formatDt(double dt) {
    return QString::fromStdString(formatStep(dt))
        .replace(QLatin1Char('.'), ui::shownLocale().decimalPoint());
}

// A list of numbers whose decimal separator is a comma is separated by semicolons.
bool commaIsDecimal() {
    return ui::shownLocale().decimalPoint() == QStringLiteral(",");
}

// A number as typed: '.'-decimal, or in the window's locale; never with group separators
// (C's would read "0,01" as 1).
std::optional<double> typedNumber(const QString& text) {
    bool ok = false;
    for (QLocale locale : {QLocale::c(), ui::shownLocale()}) {
        locale.setNumberOptions(locale.numberOptions() | QLocale::RejectGroupSeparator);
        const double value = locale.toDouble(text, &ok);
        if (ok) return value;
    }
    return std::nullopt;
}

QString formatError(double e) {
    if (std::isinf(e)) return QObject::tr("diverged");
    if (std::isnan(e)) return QStringLiteral("–");
    return ui::shownNumber(e, 'e', 2);
}

}  // namespace

AccuracyDialog::AccuracyDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Accuracy Lab — what accuracy costs in time"));
    setObjectName(QStringLiteral("accuracyDialog"));
    // As large as the study's table and chart like, within the screen (a 1024 x 700 projector).
    const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1200, 800);
    resize(std::min(1200, room.width()), std::min(800, room.height()));
    setMinimumSize(std::min(900, room.width()), std::min(620, room.height()));

    // Choices: which methods, which steps, how long.
    integrators_ = new QListWidget(this);
    for (const IntegratorInfo& info : integratorRegistry()) {
        auto* item = new QListWidgetItem(ui::integratorText(info.label), integrators_);
        item->setData(Qt::UserRole,
                      QString::fromUtf8(info.name.data(), static_cast<int>(info.name.size())));
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Checked);
    }
    integrators_->setObjectName(QStringLiteral("integrators"));
    integrators_->setAccessibleName(tr("Integrators to study"));
    dts_ = new QLineEdit(this);
    dts_->setToolTip(commaIsDecimal()
                         ? tr("Step sizes, separated by semicolons; fractions such as 1/120 are "
                              "fine. The adaptive methods sweep tolerances at the first dt "
                              "instead.")
                         : tr("Step sizes, separated by commas; fractions such as 1/120 are fine. "
                              "The adaptive methods sweep tolerances at the first dt instead."));
    duration_ = new QLineEdit(this);
    duration_->setToolTip(tr("Simulated seconds each run lasts; errors are measured at the end."));
    runButton_ = new QPushButton(tr("&Run"), this);
    runButton_->setDefault(true);
    cancelButton_ = new QPushButton(tr("&Cancel"), this);
    cancelButton_->setEnabled(false);
    progress_ = new QProgressBar(this);
    auto* exportButton = new QPushButton(tr("&Export"), this);
    auto* exportMenu = new QMenu(exportButton);
    for (const QString& format :
         {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("csv")})
        exportMenu->addAction(format.toUpper() + QStringLiteral("…"), this,
                              [this, format] { exportInteractively(format); });
    exportButton->setMenu(exportMenu);

    // Left: what to study and the buttons. Right: the diagram above (it gets the room), its
    // caption, then the orders and the runs as tabs, then the cheapest settings.
    auto* choices = new QWidget(this);
    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapAllRows);
    form->addRow(tr("&dt list:"), dts_);
    form->addRow(tr("D&uration [s]:"), duration_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(runButton_);
    buttons->addWidget(cancelButton_);
    buttons->addWidget(exportButton);
    auto* integratorsLabel = new QLabel(tr("&Integrators:"), this);
    integratorsLabel->setBuddy(integrators_);
    auto* left = new QVBoxLayout(choices);
    left->setContentsMargins(0, 0, 0, 0);
    left->addWidget(integratorsLabel);
    left->addWidget(integrators_, 1);
    left->addLayout(form);
    left->addLayout(buttons);
    left->addWidget(progress_);
    choices->setMinimumWidth(230);
    choices->setMaximumWidth(300);

    // "Cheapest settings for an error of …"
    target_ = new QLineEdit(QStringLiteral("1e-4"), this);
    target_->setToolTip(tr("The largest position error you accept at the end time, in metres"));
    target_->setMaximumWidth(90);
    cheapest_ = new QLabel(this);
    cheapest_->setWordWrap(true);
    apply_ = new QPushButton(tr("&Apply to the scene"), this);
    apply_->setEnabled(false);
    auto* cheapRow = new QHBoxLayout;
    cheapRow->addWidget(new QLabel(tr("Cheapest settings for an error of"), this));
    cheapRow->addWidget(target_);
    cheapRow->addWidget(new QLabel(tr("m:"), this));
    cheapRow->addWidget(cheapest_, 1);
    cheapRow->addWidget(apply_);

    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    summary_->setObjectName(QStringLiteral("summary"));
    chart_ = new QChartView(ui::createWorkPrecisionChart({}, tr("Work-precision diagram"), font()),
                            this);
    chart_->setObjectName(QStringLiteral("workPrecisionChart"));
    chart_->installEventFilter(this);
    chart_->setRenderHint(QPainter::Antialiasing);
    // Below this the axis titles and the dt labels no longer fit (the chart elides them).
    chart_->setMinimumSize(560, 340);
    chart_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    auto* caption = new QLabel(
        tr("Each point is one run, labelled with its step dt. <b>Lower is better</b> (a smaller "
           "error) and <b>left is faster</b> (less CPU time): the best methods sit at the lower "
           "left. A steeper line is a higher order: halving dt divides the error by "
           "2<sup>p</sup>."),
        this);
    caption->setObjectName(QStringLiteral("chartCaption"));
    caption->setWordWrap(true);
    table_ = new QTableWidget(this);
    table_->setObjectName(QStringLiteral("runsTable"));
    table_->setColumnCount(9);
    table_->setHorizontalHeaderLabels({tr("integrator"), tr("dt"), tr("tolerance"), tr("steps"),
                                       tr("force evals"), tr("CPU [s]"), tr("position error [m]"),
                                       tr("energy drift [J]"), tr("order")});
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    orders_ = new QTableWidget(this);
    orders_->setObjectName(QStringLiteral("ordersTable"));
    orders_->setColumnCount(4);
    orders_->setHorizontalHeaderLabels(
        {tr("integrator"), tr("measured order"), tr("theory"), tr("what it means")});
    orders_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    orders_->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
    orders_->setWordWrap(true);
    orders_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    orders_->setToolTip(tr("Rest the mouse on a row for the whole explanation"));
    // The explanation of the chosen row in full, where a projector shows it (a tooltip it
    // does not).
    orderDetail_ = new QLabel(this);
    orderDetail_->setObjectName(QStringLiteral("orderExplanation"));
    orderDetail_->setWordWrap(true);
    orderDetail_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    connect(orders_, &QTableWidget::currentCellChanged, this, [this](int row) {
        const QTableWidgetItem* item = row >= 0 ? orders_->item(row, 0) : nullptr;
        orderDetail_->setText(
            item
                ? QStringLiteral("<b>%1</b>: %2").arg(item->text(), item->toolTip().toHtmlEscaped())
                : QString());
    });
    auto* ordersPage = new QWidget(this);
    auto* ordersLayout = new QVBoxLayout(ordersPage);
    ordersLayout->setContentsMargins(0, 0, 0, 0);
    ordersLayout->addWidget(orders_, 1);
    ordersLayout->addWidget(orderDetail_);
    auto* tables = new QTabWidget(this);
    tables->addTab(ordersPage, tr("&Orders"));
    tables->addTab(table_, tr("A&ll runs"));

    auto* diagram = new QWidget(this);
    auto* diagramLayout = new QVBoxLayout(diagram);
    diagramLayout->setContentsMargins(0, 0, 0, 0);
    diagramLayout->addWidget(chart_, 1);
    diagramLayout->addWidget(caption);
    auto* body = new QSplitter(Qt::Vertical, this);
    body->addWidget(diagram);
    body->addWidget(tables);
    body->setStretchFactor(0, 3);
    body->setStretchFactor(1, 2);
    body->setChildrenCollapsible(false);
    auto* right = new QVBoxLayout;
    right->addWidget(summary_);
    right->addWidget(body, 1);
    right->addLayout(cheapRow);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(choices);
    layout->addLayout(right, 1);

    connect(runButton_, &QPushButton::clicked, this, &AccuracyDialog::run);
    connect(cancelButton_, &QPushButton::clicked, this, &AccuracyDialog::cancel);
    connect(&study_, &AccuracyStudy::progress, this, [this](int done, int total) {
        progress_->setMaximum(total);
        progress_->setValue(done);
    });
    connect(&study_, &AccuracyStudy::finished, this, &AccuracyDialog::onFinished);
    connect(target_, &QLineEdit::textChanged, this, &AccuracyDialog::updateCheapest);
    connect(apply_, &QPushButton::clicked, this, [this] {
        if (!chosen_) return;
        emit applyRequested(QString::fromStdString(chosen_->integrator), chosen_->dt,
                            chosen_->tolerance.value_or(scene_.simulation.tolerance));
    });
}

QFont AccuracyDialog::chartFont() const {
    // The diagram's text grows with it: a full-screen dialog on a projector reads from the back
    // of the room, a small one keeps the room for the plot. One point per 45 pixels of height.
    QFont f = font();
    if (f.pointSizeF() > 0.0)
        f.setPointSizeF(std::clamp(chart_->height() / 45.0, f.pointSizeF(), 18.0));
    return f;
}

bool AccuracyDialog::eventFilter(QObject* watched, QEvent* event) {
    if (watched == chart_ && event->type() == QEvent::Resize) {
        const QFont f = chartFont();
        if (f != chartFont_) {
            chartFont_ = f;
            ui::setWorkPrecisionFont(chart_->chart(), f);
        }
    }
    return QDialog::eventFilter(watched, event);
}

void AccuracyDialog::setCurrentScene(const SceneDesc& scene) {
    // The same scene apart from its simulation settings, compared as the file it would save.
    const auto withoutSettings = [](SceneDesc s) {
        s.simulation = SimulationDesc{};
        return SceneIO::serialize(s);
    };
    const bool current = withoutSettings(scene) == withoutSettings(studied_);
    if (current == studiedIsCurrent_) return;
    studiedIsCurrent_ = current;
    updateCheapest();
}

void AccuracyDialog::setScene(const SceneDesc& scene) {
    scene_ = scene;
    dts_->setText(dtListText(defaultAccuracyDts(scene.simulation.dt)));
    // Long scenes make long studies: 60 runs of the whole duration. A few seconds show the
    // orders as well.
    duration_->setText(ui::shownNumber(std::min(scene.simulation.duration, 5.0), 'g', 6));
    summary_->setText(tr("Scene: %1. Press Run: every checked method runs the scene at every dt "
                         "on a copy; the open scene is not touched.")
                          .arg(ui::sceneText(scene.name).toHtmlEscaped()));
}

std::optional<std::vector<double>> AccuracyDialog::parseDtList(const QString& text, QString* bad) {
    const QRegularExpression separators(commaIsDecimal() ? QStringLiteral(";")
                                                         : QStringLiteral("[;,]"));
    std::vector<double> dts;
    for (const QString& part : text.split(separators, Qt::SkipEmptyParts)) {
        const QString step = part.trimmed();
        if (step.isEmpty()) continue;
        std::optional<double> value;
        if (step.count(QLatin1Char('/')) == 1) {
            const std::optional<double> a =
                typedNumber(step.section(QLatin1Char('/'), 0, 0).trimmed());
            const std::optional<double> b =
                typedNumber(step.section(QLatin1Char('/'), 1, 1).trimmed());
            if (a && b && *b != 0.0) value = *a / *b;
        } else {
            value = typedNumber(step);
        }
        if (!value || !(*value > 0.0) || *value > 1.0) {
            if (bad) *bad = step;
            return std::nullopt;
        }
        dts.push_back(*value);
    }
    return dts;
}

QString AccuracyDialog::dtListText(const std::vector<double>& dts) {
    QStringList texts;
    for (double dt : dts) texts << formatDt(dt);
    return texts.join(commaIsDecimal() ? QStringLiteral("; ") : QStringLiteral(", "));
}

bool AccuracyDialog::run() {
    AccuracyOptions options;
    for (int i = 0; i < integrators_->count(); ++i)
        if (integrators_->item(i)->checkState() == Qt::Checked)
            options.integrators.push_back(
                integrators_->item(i)->data(Qt::UserRole).toString().toStdString());
    if (options.integrators.empty()) {
        summary_->setText(tr("Check at least one integrator."));
        return false;
    }
    QString bad;
    const std::optional<std::vector<double>> dts = parseDtList(dts_->text(), &bad);
    if (!dts) {
        summary_->setText(
            tr("dt list: \"%1\" is not a step in (0, 1] s.").arg(bad.toHtmlEscaped()));
        return false;
    }
    options.dts = *dts;
    const std::optional<double> duration = typedNumber(duration_->text().trimmed());
    options.duration = duration.value_or(0.0);
    options.durationIsDefault = !duration_->isModified();
    if (!duration || !(options.duration > 0.0) || options.duration > 1e5) {
        summary_->setText(tr("Duration: a number of seconds > 0, please."));
        return false;
    }
    if (!study_.start(scene_, options)) return false;
    studied_ = scene_;
    studiedIsCurrent_ = true;
    runButton_->setEnabled(false);
    cancelButton_->setEnabled(true);
    progress_->setValue(0);
    summary_->setText(tr("Running…"));
    return true;
}

void AccuracyDialog::cancel() {
    study_.cancel();
}

void AccuracyDialog::onFinished() {
    runButton_->setEnabled(true);
    cancelButton_->setEnabled(false);
    const AccuracyResult& result = study_.result();
    if (!result.error.empty() && result.records.empty()) {
        summary_->setText(
            tr("The study could not run: %1").arg(QString::fromStdString(result.error)));
        return;
    }
    std::vector<ui::WorkPrecisionPoint> points;
    for (const AccuracyRecord& r : result.records)
        points.push_back(
            {QString::fromStdString(r.integrator), r.cpuSeconds, r.positionError,
             r.tolerance ? QStringLiteral("tol %1").arg(*r.tolerance, 0, 'g', 1) : formatDt(r.dt)});
    QChart* old = chart_->chart();
    chart_->setChart(ui::createWorkPrecisionChart(points,
                                                  tr("%1: error at t = %2 s against CPU time")
                                                      .arg(ui::sceneText(scene_.name))
                                                      .arg(result.endTime),
                                                  chartFont()));
    delete old;
    fillTable(result);
    summary_->setText(summaryText());
    updateCheapest();
}

QString AccuracyDialog::summaryText() const {
    const AccuracyResult& result = study_.result();
    QString text = tr("Reference: %1. %2 runs%3.")
                       .arg(QString::fromStdString(result.reference))
                       .arg(result.records.size())
                       .arg(result.cancelled ? tr(" (cancelled)") : QString());
    if (result.contacts)
        text += QLatin1Char(' ') + tr("This scene has contacts: ") +
                QString::fromStdString(result.note) + QLatin1Char('.');
    if (result.endTimeMoved)
        text += QLatin1Char(' ') +
                tr("The end time was moved to %1 s, where the motion is fastest: at a turning "
                   "point every method looks better than it is.")
                    .arg(result.endTime, 0, 'g', 6);
    for (const std::string& warning : result.warnings)
        text += QStringLiteral(" ⚠ ") + QString::fromStdString(warning) + QLatin1Char('.');
    return text;
}

std::optional<double> AccuracyDialog::observedOrder(const AccuracyResult& result,
                                                    const std::string& integrator) {
    for (const OrderAssessment& a : assessOrders(result))
        if (a.integrator == integrator) return a.measured;
    return std::nullopt;
}

void AccuracyDialog::fillTable(const AccuracyResult& result) {
    const std::vector<OrderAssessment> assessments = assessOrders(result);
    const auto assessmentOf = [&](const std::string& name) -> const OrderAssessment* {
        for (const OrderAssessment& a : assessments)
            if (a.integrator == name) return &a;
        return nullptr;
    };
    table_->setRowCount(static_cast<int>(result.records.size()));
    int row = 0;
    for (const AccuracyRecord& r : result.records) {
        // A run's order with what it is worth: the pair of steps it was measured on may be
        // unstable or at the floor, where the number is not the method's order.
        const OrderAssessment* a = assessmentOf(r.integrator);
        QString order = r.order ? ui::shownNumber(*r.order, 'f', 2) : QString();
        QString orderTip;
        if (r.diverged) {
            order = tr("diverged: unstable at this dt");
            orderTip = QString::fromStdString(r.divergence);
        } else if (a && a->unstableUpToDt && r.dt >= *a->unstableUpToDt) {
            order +=
                (order.isEmpty() ? QString() : QStringLiteral("  ")) + tr("unstable at this dt");
            orderTip =
                tr("The error does not shrink as the step is halved here: the method is "
                   "unstable at this step, so this number is not its order.");
        } else if (a && a->floorFromDt && r.dt <= *a->floorFromDt && r.order) {
            order +=
                QStringLiteral("  ") + (result.referenceExact ? tr("round-off floor reached")
                                                              : tr("reference's accuracy reached"));
            orderTip =
                tr("The error is already as small as rounding (or the reference) allows: "
                   "smaller steps no longer improve it, so this number is not the "
                   "method's order.");
        }
        const QStringList cells = {QString::fromStdString(r.integrator),
                                   formatDt(r.dt),
                                   r.tolerance ? ui::shownNumber(*r.tolerance, 'g', 2) : QString(),
                                   QString::number(r.steps),
                                   QString::number(r.forceEvals),
                                   ui::shownNumber(r.cpuSeconds, 'g', 3),
                                   formatError(r.positionError),
                                   ui::shownNumber(r.energyDrift, 'e', 2),
                                   order};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c == 8 && !orderTip.isEmpty()) item->setToolTip(orderTip);
            table_->setItem(row, c, item);
        }
        ++row;
    }
    orders_->setRowCount(static_cast<int>(assessments.size()));
    row = 0;
    for (const OrderAssessment& a : assessments) {
        const QString tip = QString::fromStdString(a.explanation);
        const QStringList cells = {
            QString::fromStdString(a.integrator),
            a.measured ? ui::shownNumber(*a.measured, 'f', 2) : QStringLiteral("–"),
            a.theory > 0 ? QString::number(a.theory) : QString(), QString::fromStdString(a.note)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setToolTip(tip);
            if (c == 1 || c == 2) item->setTextAlignment(Qt::AlignCenter);
            orders_->setItem(row, c, item);
        }
        ++row;
    }
    orders_->resizeRowsToContents();
    // The first method whose number needs words, else the first.
    int chosen = 0;
    for (std::size_t i = 0; i < assessments.size(); ++i) {
        const OrderAssessment& a = assessments[i];
        const bool odd = (a.kind != OrderAssessment::Kind::AsExpected &&
                          a.kind != OrderAssessment::Kind::NotMeasured) ||
                         a.floorFromDt || a.unstableUpToDt || a.preAsymptoticUpToDt;
        if (odd) {
            chosen = static_cast<int>(i);
            break;
        }
    }
    if (orders_->rowCount() > 0) {
        orders_->setCurrentCell(-1, -1);
        orders_->setCurrentCell(chosen, 0);
    }
}

QString AccuracyDialog::orderExplanation(const QString& integrator) const {
    for (const OrderAssessment& a : assessOrders(study_.result()))
        if (a.integrator == integrator.toStdString()) return QString::fromStdString(a.explanation);
    return {};
}

std::optional<AccuracyRecord> AccuracyDialog::cheapestFor(double targetError) const {
    std::optional<AccuracyRecord> best;
    for (const AccuracyRecord& r : study_.result().records) {
        if (r.diverged || !(r.positionError <= targetError)) continue;
        if (!best || r.cpuSeconds < best->cpuSeconds) best = r;
    }
    return best;
}

void AccuracyDialog::updateCheapest() {
    bool ok = false;
    const double target = target_->text().toDouble(&ok);
    chosen_.reset();
    apply_->setEnabled(false);
    if (!ok || !(target > 0.0)) {
        cheapest_->setText(tr("type an error such as 1e-4"));
        return;
    }
    if (study_.result().records.empty()) {
        cheapest_->setText(tr("run the study first"));
        return;
    }
    chosen_ = cheapestFor(target);
    if (!chosen_) {
        cheapest_->setText(tr("no run reached it: try smaller steps or a higher-order method"));
        return;
    }
    if (!studiedIsCurrent_) {
        chosen_.reset();
        cheapest_->setText(tr("the scene has changed since this study: run it again to apply"));
        return;
    }
    cheapest_->setText(
        tr("<b>%1</b> at dt %2%3: error %4 m in %5 s of CPU")
            .arg(QString::fromStdString(chosen_->integrator), formatDt(chosen_->dt),
                 chosen_->tolerance
                     ? tr(", tolerance %1").arg(ui::shownNumber(*chosen_->tolerance, 'g', 2))
                     : QString(),
                 formatError(chosen_->positionError))
            .arg(ui::shownNumber(chosen_->cpuSeconds, 'g', 3)));
    apply_->setEnabled(true);
}

bool AccuracyDialog::exportTo(const QString& path, QString* error) const {
    if (!Document::mayWriteOutput(path, sceneFile_, error)) return false;
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
        OutputFile file(path, tr("the CSV file"));
        if (!file.open()) {
            if (error) *error = file.error();
            return false;
        }
        QTextStream out(file.device());
        out << "integrator,dt,steps,force_evals,cpu_seconds,position_error,energy_drift,order,"
               "tolerance\n";
        for (const AccuracyRecord& r : study_.result().records)
            out << QString::fromStdString(r.integrator) << ',' << formatNumber(r.dt) << ','
                << r.steps << ',' << r.forceEvals << ',' << formatNumber(r.cpuSeconds) << ','
                << formatNumber(r.positionError) << ',' << formatNumber(r.energyDrift) << ','
                << (r.order ? formatNumber(*r.order) : QString()) << ','
                << (r.tolerance ? formatNumber(*r.tolerance) : QString()) << '\n';
        out.flush();
        if (!file.commit()) {
            if (error) *error = file.error();
            return false;
        }
        return true;
    }
    std::vector<ui::WorkPrecisionPoint> points;
    for (const AccuracyRecord& r : study_.result().records)
        points.push_back(
            {QString::fromStdString(r.integrator), r.cpuSeconds, r.positionError,
             r.tolerance ? QStringLiteral("tol %1").arg(*r.tolerance, 0, 'g', 1) : formatDt(r.dt)});
    std::unique_ptr<QChart> chart(ui::createWorkPrecisionChart(
        points, tr("%1: error against CPU time").arg(ui::sceneText(scene_.name))));
    return writeChart(chart.get(), path, QSize(1400, 900), error);
}

void AccuracyDialog::exportInteractively(const QString& format) {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export"), QStringLiteral("accuracy.") + format,
        format.toUpper() + QStringLiteral(" (*.") + format + QLatin1Char(')'));
    if (path.isEmpty()) return;
    QString error;
    if (!exportTo(path, &error)) QMessageBox::warning(this, tr("Export failed"), error);
}

}  // namespace phasebox
