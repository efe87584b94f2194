#pragma once
// The instruments' graphs: any probe against time or against another probe, several at once,
// stacked in a splitter. Each graph has its two probe pickers, an export menu (PNG, SVG, CSV)
// and a close button; "Add graph" adds one below. The charts are ui/plots/ProbeChart's.
//
// The view only shows and asks: the app checks the probes, records them and exports.

#include <QFrame>
#include <QList>
#include <QPointF>
#include <QString>
#include <QVector>

#include <optional>

QT_BEGIN_NAMESPACE
class QChartView;
class QLabel;
class QSplitter;
class QToolButton;
QT_END_NAMESPACE

namespace phasebox::ui {

class ProbePicker;

class ProbeGraphView : public QFrame {
    Q_OBJECT

public:
    explicit ProbeGraphView(QWidget* parent = nullptr);

    ProbePicker* yPicker() const { return y_; }
    ProbePicker* xPicker() const { return x_; }  // its first item, "time", enters ""
    QChartView* chartView() const { return view_; }

    // Draws the samples (ProbeChart.h): against time when timeAxis. The vertical axis is
    // titled with the unit alone (the probe is named in the box above it: a graph a few
    // lines high has no room for "system.angular_momentum [kg·m²/s]" up its side).
    // cursor: the moment the timeline shows, marked as the plots mark it (Charts.h): on a graph
    // against time a line at its x (the time), on a graph against a probe a dot at it (the
    // probes' values then); none at the live end.
    void setSeries(const QVector<QPointF>& points, const QString& xTitle, const QString& yUnit,
                   bool timeAxis, std::optional<QPointF> cursor = std::nullopt);
    // A line above the chart: how to start, or why a probe is not valid (warning: in red).
    void setMessage(const QString& text, bool warning);
    QString message() const;
    // The number of points the chart's lines draw (the cursor's not counted).
    int pointCount() const;
    // The cursor's points: the line's two ends or the dot; empty when there is none.
    QVector<QPointF> cursor() const;

signals:
    void yEntered(const QString& probe);
    void xEntered(const QString& probe);  // "" for time
    void exportRequested(const QString& format);
    void removeRequested();

private:
    ProbePicker* y_ = nullptr;
    ProbePicker* x_ = nullptr;
    QChartView* view_ = nullptr;
    QLabel* message_ = nullptr;
};

class GraphsView : public QWidget {
    Q_OBJECT

public:
    static constexpr int kMaxGraphs = 6;

    explicit GraphsView(QWidget* parent = nullptr);

    int count() const { return static_cast<int>(graphs_.size()); }
    ProbeGraphView* graph(int index) const { return graphs_.value(index); }
    // Adds a graph at the end (emits graphAdded); nullptr when there are kMaxGraphs.
    ProbeGraphView* addGraph();
    // Removes one (emits graphRemoved); the last graph stays, emptied instead.
    void removeGraph(int index);
    // The probes every picker offers.
    void setOffered(const QStringList& probes);

signals:
    void graphAdded(int index);
    void graphRemoved(int index);
    void yEntered(int index, const QString& probe);
    void xEntered(int index, const QString& probe);
    void exportRequested(int index, const QString& format);

private:
    int indexOf(const ProbeGraphView* graph) const;

    QSplitter* splitter_ = nullptr;
    QToolButton* add_ = nullptr;
    QList<ProbeGraphView*> graphs_;
    QStringList offered_;
};

}  // namespace phasebox::ui
