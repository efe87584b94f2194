#pragma once
// Readouts of the selected object: position, velocity, speed, angle and ω (rigid bodies),
// kinetic energy, momentum and angular momentum, each from its probe, under a line that says
// whose values they are: the live state ("live, t = 1.23 s"), a recorded moment the timeline shows
// ("recorded, t = 0.62 s") or the setup. With two or three
// objects selected it reads the distance and the angle between them; with a joint, its force.
//
// Right-click a row (or double-click it) to graph its probe or time its period.

#include <QList>
#include <QString>
#include <QStringList>
#include <QVector>
#include <QWidget>

QT_BEGIN_NAMESPACE
class QLabel;
class QTableWidget;
QT_END_NAMESPACE

namespace phasebox::ui {

struct ReadoutRow {
    QString label;           // "position"
    QVector<double> values;  // one, or two for a vector: (x, y)
    QString unit;            // "m"
    QStringList probes;      // the probes read, one per value
};

class ReadoutView : public QWidget {
    Q_OBJECT

public:
    explicit ReadoutView(QWidget* parent = nullptr);

    // Whose values: the setup's, the live run's or a recorded moment's; each its own tint.
    enum class Source { Setup, Live, Recorded };
    // subject: "p0 (particle)"; state: "live, t = 1.23 s", "recorded, t = 0.62 s" or "setup",
    // tinted as source.
    void setReadout(const QString& subject, const QString& state, Source source,
                    const QList<ReadoutRow>& rows);
    // Nothing to read: the hint says how to choose something.
    void showHint(const QString& hint);

    QString subject() const;
    QString state() const;
    // The value column's text of the row with this label ("" when there is none).
    QString valueText(const QString& label) const;
    // The values of the row with this label, as read (empty when there is none).
    QVector<double> values(const QString& label) const;
    int rowCount() const;

signals:
    void graphRequested(const QString& probe);
    void periodRequested(const QString& probe);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void showMenu(const QPoint& position);
    void fitColumns();

    QLabel* subject_ = nullptr;
    QLabel* state_ = nullptr;
    QLabel* hint_ = nullptr;
    QTableWidget* table_ = nullptr;
    QList<ReadoutRow> rows_;
};

}  // namespace phasebox::ui
