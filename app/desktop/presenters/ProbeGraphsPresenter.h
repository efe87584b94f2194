#pragma once
// The Instruments dock's graphs (Graphs tab): each plots a probe against time or against another
// probe from the recorded samples, and exports as PNG, SVG or CSV.

#include "app/desktop/presenters/InstrumentBase.h"

#include <QPointF>
#include <QString>
#include <QVector>

#include <optional>
#include <vector>

namespace phasebox {

class ProbeGraphsPresenter : public InstrumentBase {
    Q_OBJECT

public:
    struct Graph {
        QString y, x;  // x empty: against time
    };

    ProbeGraphsPresenter(ui::InstrumentsPanel& panel, Document& document, ProbeRecorder& probes,
                         QObject* parent = nullptr);

    void refresh() override;

    // Plots y against x ("" = time) in the first empty graph, or a new one; false with a
    // message (and *error) when either is not a probe of the scene or no graph is left.
    bool plotProbe(const QString& y, const QString& x = {}, QString* error = nullptr);
    // Sets graph index's probes; false (graph unchanged) when one is not a probe.
    bool setGraph(int index, const QString& y, const QString& x = {}, QString* error = nullptr);
    const std::vector<Graph>& graphs() const { return graphs_; }
    // Clears the pickers' marks of invalid probes (a new scene).
    void clearInvalid();

    // A graph as PNG, SVG (its chart, 1200 × 800) or CSV (t, then x when against a probe, then
    // y), chosen by the file's extension.
    bool exportGraph(int index, const QString& path, QString* error) const;

private:
    void refreshGraph(int index);
    // The samples of a graph: (time or x, y), NaN where a probe had none.
    QVector<QPointF> graphPoints(const Graph& graph) const;
    // The timeline's moment in a graph: (time or x, y) then; none at the live end.
    std::optional<QPointF> cursor(const Graph& graph) const;
    QString axisTitle(const QString& probe) const;
    void exportGraphInteractively(int index, const QString& format);

    std::vector<Graph> graphs_;
};

}  // namespace phasebox
