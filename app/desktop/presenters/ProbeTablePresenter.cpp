#include "app/desktop/presenters/ProbeTablePresenter.h"

#include "app/document/Document.h"
#include "app/sim/ProbeRecorder.h"
#include "ui/instruments/InstrumentsPanel.h"
#include "ui/instruments/ProbeFormat.h"
#include "ui/instruments/ProbePicker.h"
#include "ui/instruments/ProbeTableView.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFileDialog>
#include <QMessageBox>
#include <QStandardPaths>
#include <QVector>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace phasebox {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

ProbeTablePresenter::ProbeTablePresenter(ui::InstrumentsPanel& panel, Document& document,
                                         ProbeRecorder& probes, QObject* parent)
    : InstrumentBase(panel, document, probes, parent) {
    connect(&probes_, &ProbeRecorder::cleared, this, [this] { ++clears_; });
    ui::ProbeTableView* table = panel_.table();
    connect(table, &ui::ProbeTableView::columnEntered, this,
            [this](const QString& p) { addColumn(p); });
    connect(table, &ui::ProbeTableView::columnRemoved, this, &ProbeTablePresenter::removeColumn);
    connect(table, &ui::ProbeTableView::exportRequested, this,
            &ProbeTablePresenter::exportTableInteractively);
    connect(table, &ui::ProbeTableView::copyRequested, this, &ProbeTablePresenter::copyTable);
}

bool ProbeTablePresenter::addColumn(const QString& probe, QString* error) {
    if (probe.isEmpty() || !check(probe, panel_.table()->picker(), error)) return false;
    panel_.table()->picker()->setProbe({});
    if (!columns_.contains(probe)) columns_ << probe;
    panel_.table()->setOwnColumns(columns_);
    emit probesChanged();
    refresh();
    return true;
}

void ProbeTablePresenter::removeColumn(const QString& probe) {
    columns_.removeAll(probe);
    panel_.table()->setOwnColumns(columns_);
    emit probesChanged();
    refresh();
}

void ProbeTablePresenter::setColumns(const QStringList& probes) {
    columns_.clear();
    for (const QString& probe : probes)
        if (!columns_.contains(probe)) columns_ << probe;
    panel_.table()->picker()->setInvalid({});
    panel_.table()->setOwnColumns(columns_);
}

void ProbeTablePresenter::refresh() {
    QStringList headers{tr("t [s]")};
    const std::vector<double>& times = probes_.times();
    // Each column's largest magnitude sets its decimals (the time's: microseconds).
    QVector<double> scales{1.0};
    for (int i = 0; i < probes_.probeCount(); ++i) {
        const QString text = probes_.probeText(i);
        headers << (probes_.isValid(i) ? ui::probeTitle(text, probes_.parsed(i)->kind)
                                       : tr("%1 (invalid)").arg(text));
        double scale = 0.0;
        for (const double v : probes_.values(i))
            if (std::isfinite(v)) scale = std::max(scale, std::abs(v));
        scales << scale;
    }
    const ProbeRecorder* probes = &probes_;
    const auto source = [probes](int row, int column) {
        const std::vector<double>& t = probes->times();
        if (row < 0 || static_cast<std::size_t>(row) >= t.size()) return kNaN;
        if (column == 0) return t[static_cast<std::size_t>(row)];
        if (column - 1 >= probes->probeCount()) return kNaN;
        const std::vector<double>& v = probes->values(column - 1);
        return static_cast<std::size_t>(row) < v.size() ? v[static_cast<std::size_t>(row)] : kNaN;
    };
    panel_.table()->setTable(headers, static_cast<int>(times.size()), source,
                             clears_ * 64 + static_cast<long long>(std::log2(probes_.stride())),
                             scales);
    // The timeline's moment: the last sample at or before it (its own, unless the series was
    // thinned since).
    const double shown = shownTime();
    int row = -1;
    if (!std::isnan(shown))
        row =
            static_cast<int>(std::upper_bound(times.begin(), times.end(), shown) - times.begin()) -
            1;
    panel_.table()->setShownRow(row);
}

bool ProbeTablePresenter::exportTable(const QString& path, QString* error) const {
    if (!document_.mayWriteOutput(path, error)) return false;
    return probes_.writeCsv(path, {}, error);
}

void ProbeTablePresenter::copyTable() const {
    const auto [first, last] = panel_.table()->selectedRows();
    QApplication::clipboard()->setText(probes_.text({}, QLatin1Char('\t'), first, last));
}

void ProbeTablePresenter::exportTableInteractively() {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getSaveFileName(
        panel_.window(), tr("Export Probe Table"), QDir(dir).filePath(QStringLiteral("probes.csv")),
        tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportTable(path, &error))
        QMessageBox::warning(panel_.window(), tr("Export failed"), error);
    else
        emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(path)));
}

}  // namespace phasebox
