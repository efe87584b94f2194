#include "app/io/ChartFile.h"

#include "app/io/OutputFile.h"
#include "ui/plots/Charts.h"

#include <QFileInfo>

namespace phasebox {

bool isChartPath(const QString& path, QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("png") || suffix == QLatin1String("svg")) return true;
    if (error) *error = QStringLiteral("%1: the plot must be a .png or .svg file").arg(path);
    return false;
}

bool writeChart(QChart* chart, const QString& path, QSize size, QString* error) {
    if (!isChartPath(path, error)) return false;
    const QByteArray bytes = ui::renderChart(chart, QFileInfo(path).suffix().toLower(), size);
    if (bytes.isEmpty()) {
        if (error) *error = QStringLiteral("%1: cannot draw the plot").arg(path);
        return false;
    }
    return OutputFile::writeAll(path, bytes, error, QStringLiteral("the plot"));
}

}  // namespace phasebox
