#include "ui/instruments/ReadoutView.h"

#include "ui/instruments/ProbeFormat.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QResizeEvent>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace phasebox::ui {

namespace {
enum Column { kQuantity, kValue, kUnit, kColumns };

QString joined(const QVector<double>& values) {
    if (values.size() == 1) return formatReading(values.front());
    QStringList parts;
    for (const double v : values) parts << formatReading(v);
    // A decimal comma needs another separator between the numbers of a pair.
    const QString separator = QLocale().decimalPoint() == QLatin1String(",") ? QStringLiteral("; ")
                                                                             : QStringLiteral(", ");
    return QLatin1Char('(') + parts.join(separator) + QLatin1Char(')');
}
}  // namespace

ReadoutView::ReadoutView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    auto* header = new QHBoxLayout;
    subject_ = new QLabel(this);
    subject_->setObjectName(QStringLiteral("readoutSubject"));
    QFont bold = subject_->font();
    bold.setBold(true);
    subject_->setFont(bold);
    subject_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    state_ = new QLabel(this);
    state_->setObjectName(QStringLiteral("readoutState"));
    state_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    header->addWidget(subject_, 1);
    header->addWidget(state_);
    layout->addLayout(header);

    hint_ = new QLabel(this);
    hint_->setWordWrap(true);
    hint_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(hint_, 1);  // top-aligned, it takes the room the hidden table leaves

    table_ = new QTableWidget(0, kColumns, this);
    table_->setObjectName(QStringLiteral("readoutTable"));
    table_->setHorizontalHeaderLabels({tr("quantity"), tr("value"), tr("unit")});
    table_->verticalHeader()->hide();
    table_->setShowGrid(false);
    table_->setAlternatingRowColors(true);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setContextMenuPolicy(Qt::CustomContextMenu);
    table_->horizontalHeader()->setSectionResizeMode(kQuantity, QHeaderView::Interactive);
    table_->horizontalHeader()->setSectionResizeMode(kValue, QHeaderView::Stretch);
    table_->horizontalHeader()->setSectionResizeMode(kUnit, QHeaderView::ResizeToContents);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setToolTip(tr("Right-click a row to graph it or time its period"));
    connect(table_, &QWidget::customContextMenuRequested, this, &ReadoutView::showMenu);
    connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
        if (row >= 0 && row < rows_.size() && !rows_[row].probes.isEmpty())
            emit graphRequested(rows_[row].probes.front());
    });
    layout->addWidget(table_, 1);
    showHint(tr("Click an object on the canvas to read its state."));
}

void ReadoutView::setReadout(const QString& subject, const QString& state, Source source,
                             const QList<ReadoutRow>& rows) {
    hint_->hide();
    table_->show();
    subject_->setText(subject);
    state_->setText(state);
    // Live values in (Okabe–Ito) bluish green, a recorded moment in blue, the setup in grey
    // (each at least 4.5:1 against white), each also named in its text: a glance tells which is
    // shown, whatever colours one sees.
    const QString background = source == Source::Live       ? QStringLiteral("#007a5a")
                               : source == Source::Recorded ? QStringLiteral("#0072b2")
                                                            : QStringLiteral("#7f7f7f");
    state_->setStyleSheet(
        QStringLiteral("QLabel { color: white; background: %1; border-radius: 3px; "
                       "padding: 1px 6px; }")
            .arg(background));
    const bool sameRows = rows.size() == rows_.size() &&
                          std::equal(rows.begin(), rows.end(), rows_.begin(),
                                     [](const ReadoutRow& a, const ReadoutRow& b) {
                                         return a.label == b.label && a.probes == b.probes;
                                     });
    rows_ = rows;
    const QFont digits = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    if (!sameRows) {
        table_->setRowCount(static_cast<int>(rows.size()));
        for (int r = 0; r < rows.size(); ++r) {
            auto* quantity = new QTableWidgetItem(rows[r].label);
            quantity->setToolTip(rows[r].probes.join(QStringLiteral(", ")));
            table_->setItem(r, kQuantity, quantity);
            auto* value = new QTableWidgetItem;
            value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            value->setFont(digits);
            table_->setItem(r, kValue, value);
            table_->setItem(r, kUnit, new QTableWidgetItem(rows[r].unit));
        }
    }
    for (int r = 0; r < rows.size(); ++r) table_->item(r, kValue)->setText(joined(rows[r].values));
    if (!sameRows) fitColumns();
}

void ReadoutView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitColumns();
}

// The quantity column as wide as its longest name, but no wider than leaves the values room for
// a pair's first number and the units theirs: a long name wraps at its spaces ("Betrag der /
// Geschwindigkeit") rather than cut a value to "(−2,000…" (German names are long).
void ReadoutView::fitColumns() {
    const QFontMetrics names(table_->font());
    const QFontMetrics digits(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    constexpr int kPad = 14;
    int whole = names.horizontalAdvance(table_->horizontalHeaderItem(kQuantity)->text());
    int word = 0;
    for (const ReadoutRow& row : std::as_const(rows_)) {
        whole = std::max(whole, names.horizontalAdvance(row.label));
        for (const QString& w : row.label.split(QLatin1Char(' '), Qt::SkipEmptyParts))
            word = std::max(word, names.horizontalAdvance(w));
    }
    const int value = digits.horizontalAdvance(QStringLiteral("(−0,00000;")) + kPad;
    const int room = table_->viewport()->width() - table_->columnWidth(kUnit) - value;
    table_->setColumnWidth(kQuantity, std::clamp(room, word + kPad, std::max(word, whole) + kPad));
    table_->resizeRowsToContents();
}

void ReadoutView::showHint(const QString& hint) {
    rows_.clear();
    table_->setRowCount(0);
    table_->hide();
    subject_->clear();
    state_->clear();
    state_->setStyleSheet(QString());
    hint_->setText(hint);
    hint_->show();
}

QString ReadoutView::subject() const {
    return subject_->text();
}

QString ReadoutView::state() const {
    return state_->text();
}

QString ReadoutView::valueText(const QString& label) const {
    for (int r = 0; r < rows_.size(); ++r)
        if (rows_[r].label == label) return table_->item(r, kValue)->text();
    return {};
}

QVector<double> ReadoutView::values(const QString& label) const {
    for (const ReadoutRow& row : rows_)
        if (row.label == label) return row.values;
    return {};
}

int ReadoutView::rowCount() const {
    return static_cast<int>(rows_.size());
}

void ReadoutView::showMenu(const QPoint& position) {
    const int row = table_->rowAt(position.y());
    if (row < 0 || row >= rows_.size()) return;
    QMenu menu(this);
    for (const QString& probe : rows_[row].probes)
        menu.addAction(tr("Graph %1 against time").arg(probe), this,
                       [this, probe] { emit graphRequested(probe); });
    menu.addSeparator();
    for (const QString& probe : rows_[row].probes)
        menu.addAction(tr("Time the period of %1").arg(probe), this,
                       [this, probe] { emit periodRequested(probe); });
    menu.exec(table_->viewport()->mapToGlobal(position));
}

}  // namespace phasebox::ui
