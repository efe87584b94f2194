#include "ui/instruments/ProbeTableView.h"

#include "ui/instruments/ProbePicker.h"
#include "ui/panels/ShownNumber.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLabel>
#include <QMenu>
#include <QScrollBar>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace phasebox::ui {

// ---- the model ----------------------------------------------------------------------------------

void ProbeTableModel::setTable(const QStringList& headers, int rows, Source source,
                               long long layoutKey, const QVector<double>& scales) {
    source_ = std::move(source);
    QVector<int> decimals;
    for (const double scale : scales)
        decimals << (!(scale > 0.0) || !std::isfinite(scale) ? 6
                     : scale < 1e-3 || scale >= 1e7
                         ? -1
                         : std::clamp(6 - static_cast<int>(std::floor(std::log10(scale))), 0, 9));
    if (decimals != decimals_) {
        decimals_ = decimals;
        if (rows_ > 0 && !headers_.isEmpty())
            emit dataChanged(index(0, 0), index(rows_ - 1, columnCount() - 1));
    }
    if (headers != headers_ || rows < rows_ || layoutKey != layoutKey_) {
        beginResetModel();
        headers_ = headers;
        rows_ = rows;
        layoutKey_ = layoutKey;
        endResetModel();
        return;
    }
    if (rows > rows_) {
        beginInsertRows({}, rows_, rows - 1);
        rows_ = rows;
        endInsertRows();
    }
    // The last row may have been filled in since (a probe added at the current time).
    if (rows_ > 0) emit dataChanged(index(rows_ - 1, 0), index(rows_ - 1, columnCount() - 1));
}

int ProbeTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : rows_;
}

int ProbeTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(headers_.size());
}

QVariant ProbeTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !source_) return {};
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::UserRole) return {};
    const double value = source_(index.row(), index.column());
    if (role == Qt::UserRole) return value;
    if (std::isnan(value)) return QString();
    // Seven significant digits at the column's largest value (which tells a conserved quantity
    // from one that drifts), the same decimals all down the column so that the points line up.
    const int decimals = decimals_.value(index.column(), 6);
    // Shown in the locale; Copy and Export CSV write the recorder's '.'-decimal numbers.
    return decimals < 0 ? shownNumber(value, 'e', 6) : shownNumber(value, 'f', decimals);
}

QVariant ProbeTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    return headers_.value(section);
}

// ---- the view -----------------------------------------------------------------------------------

ProbeTableView::ProbeTableView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* bar = new QHBoxLayout;
    picker_ = new ProbePicker(tr("add a column"), {}, this);
    picker_->setObjectName(QStringLiteral("tableProbe"));
    remove_ = new QToolButton(this);
    remove_->setText(tr("Remove"));
    remove_->setToolTip(tr("Remove a column added here"));
    remove_->setPopupMode(QToolButton::InstantPopup);
    remove_->setMenu(new QMenu(remove_));
    remove_->setEnabled(false);
    auto* copy = new QToolButton(this);
    copy->setText(tr("Copy"));
    copy->setToolTip(tr("Copy the selected rows (or all) as tab-separated text"));
    auto* exportCsv = new QToolButton(this);
    exportCsv->setText(tr("Export CSV…"));
    // The picker on its own row, the buttons under it: a narrow dock shows both whole.
    layout->addWidget(picker_);
    bar->addWidget(remove_);
    bar->addWidget(copy);
    bar->addWidget(exportCsv);
    bar->addStretch(1);
    layout->addLayout(bar);
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    layout->addWidget(summary_);

    model_ = new ProbeTableModel(this);
    table_ = new QTableView(this);
    table_->setObjectName(QStringLiteral("probeTable"));
    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setAlternatingRowColors(true);
    table_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 4);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(table_, 1);

    // Ctrl+C in the table copies rows, not the scene's objects (the window's Copy).
    table_->installEventFilter(this);
    connect(copy, &QToolButton::clicked, this, &ProbeTableView::copyRequested);
    connect(exportCsv, &QToolButton::clicked, this, &ProbeTableView::exportRequested);
    connect(picker_, &ProbePicker::probeEntered, this, &ProbeTableView::columnEntered);
}

void ProbeTableView::setTable(const QStringList& headers, int rows, ProbeTableModel::Source source,
                              long long layoutKey, const QVector<double>& scales) {
    // Follow the newest rows while the view is at the bottom, as a log does.
    const QScrollBar* bar = table_->verticalScrollBar();
    const bool atBottom = bar->value() >= bar->maximum() - 1;
    model_->setTable(headers, rows, std::move(source), layoutKey, scales);
    if (atBottom) table_->scrollToBottom();
    summary_->setText(headers.size() <= 1 ? tr("No probes recorded yet: graph or time one, or "
                                               "add a column above.")
                                          : tr("%n sample(s)", nullptr, rows));
}

void ProbeTableView::setOwnColumns(const QStringList& probes) {
    QMenu* menu = remove_->menu();
    menu->clear();
    for (const QString& probe : probes)
        menu->addAction(probe, this, [this, probe] { emit columnRemoved(probe); });
    remove_->setEnabled(!probes.isEmpty());
}

bool ProbeTableView::eventFilter(QObject* watched, QEvent* event) {
    if (watched == table_ &&
        (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress) &&
        static_cast<QKeyEvent*>(event)->matches(QKeySequence::Copy)) {
        // Accepting the override keeps the key from the window's shortcut.
        event->accept();
        if (event->type() == QEvent::KeyPress) emit copyRequested();
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

std::pair<int, int> ProbeTableView::selectedRows() const {
    const QModelIndexList rows = table_->selectionModel()->selectedRows();
    if (rows.isEmpty()) return {0, -1};
    int first = rows.front().row(), last = first;
    for (const QModelIndex& i : rows) {
        first = std::min(first, i.row());
        last = std::max(last, i.row());
    }
    return {first, last};
}

void ProbeTableView::setShownRow(int row) {
    QItemSelectionModel* selection = table_->selectionModel();
    if (row < 0 || row >= model_->rowCount()) {
        if (shownRow_ >= 0) {
            selection->clear();
            table_->scrollToBottom();
        }
        shownRow_ = -1;
        return;
    }
    const QModelIndex index = model_->index(row, 0);
    // Selected anew after the model was reset (the samples were halved), but scrolled to only
    // when the moment moves, so that the user may scroll through the table meanwhile.
    if (selection->currentIndex().row() != row || !selection->isRowSelected(row))
        selection->setCurrentIndex(index,
                                   QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    if (row != shownRow_) table_->scrollTo(index, QAbstractItemView::PositionAtCenter);
    shownRow_ = row;
}

}  // namespace phasebox::ui
