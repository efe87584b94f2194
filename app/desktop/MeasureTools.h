#pragma once
// The canvas instruments: rulers, protractors and the free-body view.
//
//   Ruler       drag from one point to another; the label reads the distance (m) with dx, dy
//   Protractor  drag from the vertex along the first arm, release, then click the second arm;
//               the label reads the angle between the arms (degrees, 0 to 180)
//
// A protractor's three ends are kept, passed and written in one order everywhere, that of the
// probe angle(A,B,C): the first arm A, the vertex B in the middle, the second arm C.
//   either      drag an end of one to move it (and attach or detach it)
//
// An end pressed or dropped on a particle or rigid body attaches to its centre and follows it
// while the simulation runs (the reading is live); elsewhere it stays at that point of the
// world. Readings come from the probes' functions (physics/world/Probes: the same positions and
// signed angle as distance(A,B) and angle(A,B,C)). Each instrument is a probe: rulerProbe() and
// protractorProbe() give its text (`angle(bob,0:0,0:-1)`: an id for an attached end, `X:Y` for
// a point), the reading is that probe's value, and the Instruments dock offers it to its graphs,
// timer and table (probesChanged()). An instrument stays until removed: Esc or
// Delete on the canvas while it is selected (one just drawn is; a click on one with its tool,
// or with Select off any object, selects it), or Clear Measurements. One attached to an object that
// is deleted, or absent after a reset or an opened file, goes with it.
//
// The free-body view (View menu) draws, for the first selected body that moves, the forces on
// it by source (physics/world/FreeBody), its momentum and the system's centre of mass.

#include "app/desktop/presenters/Presenter.h"
#include "physics/world/FreeBody.h"

#include <QPointF>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace phasebox {

struct InstrumentsDesc;
class CanvasTools;
class Document;
class SimulationController;
namespace ui {
class SceneView;
}

class MeasureTools : public Presenter {
    Q_OBJECT

public:
    // One end of an instrument: attached to an object (its id) or a fixed world point.
    struct End {
        QString object;
        QPointF point;
    };

    MeasureTools(Document& document, CanvasTools& tools, ui::SceneView& view,
                 SimulationController& controller, QObject* parent = nullptr);

    void refresh() override;
    // Free-Body View (View menu, B) and Clear Measurements (Tools menu).
    void createActions(QWidget& window);

    // Parses "ID" (an object) or "X:Y" (a world point, metres); nullopt when it is neither.
    std::optional<End> parseEnd(const QString& text) const;
    void addRuler(const End& a, const End& b);
    // ∠ABC: the vertex is b, the middle end.
    void addProtractor(const End& a, const End& vertex, const End& c);
    // From the command line: "A,B" and "A,B,C" (B the vertex) with ends as parseEnd reads them;
    // false with the reason in *error.
    bool addRuler(const QString& ends, QString* error);
    bool addProtractor(const QString& ends, QString* error);
    void clear();
    // A lesson's rulers, protractors and free body (CONTRACT §7, MeasureLesson.cpp): set from
    // the opened file (replacing every instrument; New brings none), and what is set now.
    void applyInstruments(const InstrumentsDesc& instruments);
    void collectInstruments(InstrumentsDesc& instruments) const;
    // An end as a lesson file writes it: the object's id, or "X:Y".
    static QString endText(const End& end);
    // Removes the selected instrument; false when none is selected.
    bool removeSelected();

    int rulerCount() const { return static_cast<int>(rulers_.size()); }
    int protractorCount() const { return static_cast<int>(protractors_.size()); }
    // Ruler i's ends now (world), its length and label.
    QPointF rulerEnd(int ruler, int end) const;
    double rulerLength(int ruler) const;
    QString rulerLabel(int ruler) const;
    // Protractor i's angle between its arms, in degrees in [0, 180].
    double protractorDegrees(int protractor) const;
    QString protractorLabel(int protractor) const;
    // The probe each instrument reads: distance(A,B), angle(A,B,C).
    QString rulerProbe(int ruler) const;
    QString protractorProbe(int protractor) const;
    // Every instrument's probe, rulers first.
    QStringList probes() const;

    bool freeBodyShown() const { return freeBodyShown_; }
    void setFreeBodyShown(bool on);
    // The free body the view draws now (nullopt: no moving body selected).
    std::optional<FreeBody> freeBody() const;

    // Pixels within which a click selects an instrument, and a press grabs its end.
    static constexpr double kPickPixels = 6.0;
    static constexpr double kEndPickPixels = 9.0;

signals:
    void freeBodyShownChanged(bool on);
    // The instruments' probes (probes()) changed: one was added, removed or moved.
    void probesChanged();

private:
    struct Ruler {
        End ends[2];
    };
    struct Protractor {
        End ends[3];  // ∠ABC: first arm, vertex, second arm
    };
    enum class Gesture { None, Ruler, ProtractorFirstArm, ProtractorSecondArm, MoveEnd };
    enum class Kind { None, Ruler, Protractor };
    struct EndRef {
        Kind kind = Kind::None;
        int index = -1;
        int end = -1;
    };

    void pressed(QPointF world, Qt::MouseButton button);
    void moved(QPointF world, Qt::MouseButtons buttons);
    void released(QPointF world, Qt::MouseButton button);
    bool eventFilter(QObject* watched, QEvent* event) override;
    void cancelGesture();
    // An end at a world point: the particle or rigid body under it, else the point itself.
    End snap(QPointF world) const;
    // Where an end is now; the object's last place when it is gone.
    QPointF position(const End& end) const;
    bool exists(const End& end) const;
    // The instrument within kPickPixels of a world point; the end of one within
    // kEndPickPixels.
    std::pair<Kind, int> instrumentAt(QPointF world) const;
    EndRef endAt(QPointF world) const;
    End& endOf(const EndRef& ref);
    // Drops the instruments attached to objects that are gone.
    void dropOrphans();
    void select(Kind kind, int index);
    QString rulerText(QPointF a, QPointF b) const;
    QString protractorText(QPointF a, QPointF vertex, QPointF c) const;
    // An end as a probe's argument: the object's id, or the point as X:Y.
    static QString probeArgument(const End& end);
    // The instrument's reading through its probe (parsed against the world as it is now).
    double readProbe(const QString& text) const;

    Document& document_;
    CanvasTools& tools_;
    ui::SceneView& view_;
    QVector<Ruler> rulers_;
    QVector<Protractor> protractors_;
    Kind selectedKind_ = Kind::None;
    int selectedIndex_ = -1;

    Gesture gesture_ = Gesture::None;
    End pending_[3];
    QPointF pressedAt_;
    EndRef moving_;  // MoveEnd: the end dragged, and where it was (Esc puts it back)
    End movedFrom_;
    bool freeBodyShown_ = false;
    QStringList probes_;  // as last announced by probesChanged()
};

}  // namespace phasebox
