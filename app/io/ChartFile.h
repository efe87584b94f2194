#pragma once
// Saving a plot (the energy, phase and work-precision charts) as .png or .svg: drawn by
// ui::renderChart, written by OutputFile like every other file Phasebox writes.

#include <QSize>
#include <QString>

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace phasebox {

// Whether path names a plot file: .png or .svg (any case). Else "PATH: the plot must be a
// .png or .svg file" in *error.
bool isChartPath(const QString& path, QString* error = nullptr);

// Writes chart as PNG or SVG by path's extension. False with *error set ("PATH: cannot write
// the plot: REASON") on failure; an earlier file of that name is then kept whole.
bool writeChart(QChart* chart, const QString& path, QSize size, QString* error);

}  // namespace phasebox
