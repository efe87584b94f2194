#pragma once
// The data table: the recorded probes, a row per sample (time first), with CSV export and
// Copy (the selected rows, or all, as tab-separated text that a spreadsheet pastes into
// columns). Columns are the probes the graphs and the timer record, and any added here.
//
// The model reads the app's samples through a function, so a table of a long run holds no copy
// of them; its row count follows at each refresh.

#include <QAbstractTableModel>
#include <QStringList>
#include <QVector>
#include <QWidget>

#include <functional>

QT_BEGIN_NAMESPACE
class QLabel;
class QTableView;
class QToolButton;
QT_END_NAMESPACE

namespace phasebox::ui {

class ProbePicker;

class ProbeTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    // value(row, column): column 0 is the time, then one per header after it; NaN shows empty.
    using Source = std::function<double(int row, int column)>;

    using QAbstractTableModel::QAbstractTableModel;

    // headers: "t [s]" and the probes. Rows appended since the last call are inserted (the view
    // keeps its place); a new layout (other headers, fewer rows, another key: the samples were
    // halved or cleared) resets the model. scales: each column's largest magnitude, so that a
    // column shows one number of decimals (seven significant digits at its largest value).
    void setTable(const QStringList& headers, int rows, Source source, long long layoutKey,
                  const QVector<double>& scales = {});

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    QStringList headers_;
    QVector<int> decimals_;  // per column; −1: scientific
    int rows_ = 0;
    Source source_;
    long long layoutKey_ = -1;
};

class ProbeTableView : public QWidget {
    Q_OBJECT

public:
    explicit ProbeTableView(QWidget* parent = nullptr);

    ProbePicker* picker() const { return picker_; }
    QTableView* table() const { return table_; }
    ProbeTableModel* model() const { return model_; }
    void setTable(const QStringList& headers, int rows, ProbeTableModel::Source source,
                  long long layoutKey, const QVector<double>& scales = {});
    // The probes added here (they can be removed here).
    void setOwnColumns(const QStringList& probes);
    // The selected rows' range [first, last], or (0, -1) for all.
    std::pair<int, int> selectedRows() const;
    // The row of the moment the timeline shows: made current and selected, and scrolled to when
    // it changes; -1 (the live end) lets go of it and follows the newest rows again.
    void setShownRow(int row);
    int shownRow() const { return shownRow_; }

signals:
    void columnEntered(const QString& probe);
    void columnRemoved(const QString& probe);
    void exportRequested();
    void copyRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    ProbePicker* picker_ = nullptr;
    QToolButton* remove_ = nullptr;
    QLabel* summary_ = nullptr;
    QTableView* table_ = nullptr;
    ProbeTableModel* model_ = nullptr;
    int shownRow_ = -1;
};

}  // namespace phasebox::ui
