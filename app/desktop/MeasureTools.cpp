#include "app/desktop/MeasureTools.h"

#include "app/desktop/CanvasTools.h"
#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/world/Probes.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"
#include "ui/panels/ShownNumber.h"

#include <QAction>
#include <QKeyEvent>
#include <QLineF>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phasebox {

namespace {

Vec2 vec(QPointF p) {
    return {p.x(), p.y()};
}

// Pixels from p to the segment a–b (all in widget pixels).
double segmentPixels(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a;
    const double l2 = QPointF::dotProduct(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return QLineF(p, a + t * ab).length();
}

// The ends of a comma-separated list, split outside brackets (a cloth node's id holds a comma).
QStringList splitEnds(const QString& text) {
    QStringList ends;
    int depth = 0;
    QString current;
    for (const QChar c : text) {
        if (c == QLatin1Char('[')) ++depth;
        if (c == QLatin1Char(']')) depth = std::max(0, depth - 1);
        if (c == QLatin1Char(',') && depth == 0) {
            ends << current.trimmed();
            current.clear();
        } else {
            current += c;
        }
    }
    ends << current.trimmed();
    return ends;
}

}  // namespace

MeasureTools::MeasureTools(Document& document, CanvasTools& tools, ui::SceneView& view,
                           SimulationController& controller, QObject* parent)
    : Presenter(parent), document_(document), tools_(tools), view_(view) {
    connect(&view_, &ui::SceneView::worldMousePressed, this,
            [this](QPointF world, Qt::MouseButton button) { pressed(world, button); });
    connect(&view_, &ui::SceneView::worldMouseMoved, this,
            [this](QPointF world, Qt::MouseButtons buttons) { moved(world, buttons); });
    connect(&view_, &ui::SceneView::worldMouseReleased, this,
            [this](QPointF world, Qt::MouseButton button) { released(world, button); });
    view_.installEventFilter(this);  // Esc and Delete
    connect(&tools_, &CanvasTools::toolChanged, this, [this](CanvasTools::Tool tool) {
        cancelGesture();
        // A drawing tool has its own Esc (the polygon's outline): an instrument lets go.
        using T = CanvasTools::Tool;
        if (tool != T::Select && tool != T::Ruler && tool != T::Protractor) select(Kind::None, -1);
        refresh();
    });
    connect(&controller, &SimulationController::stepped, this, &MeasureTools::refresh);
    for (auto signal : {&Document::sceneReset, &Document::sceneEdited})
        connect(&document_, signal, this, [this] {
            dropOrphans();
            refresh();
        });
    connect(&document_, &Document::selectionChanged, this, &MeasureTools::refresh);
    connect(&document_, &Document::instrumentsLoaded, this,
            [this] { applyInstruments(document_.loadedInstruments()); });
}

void MeasureTools::createActions(QWidget& window) {
    QAction* freeBody =
        addWindowAction(window, QStringLiteral("freeBody"), tr("Free-&Body View"), Qt::Key_B);
    freeBody->setCheckable(true);
    freeBody->setToolTip(
        tr("Draw the forces on the selected body by source, its momentum and the system's "
           "centre of mass"));
    connect(freeBody, &QAction::toggled, this, &MeasureTools::setFreeBodyShown);
    connect(this, &MeasureTools::freeBodyShownChanged, freeBody, &QAction::setChecked);
    connect(addWindowAction(window, QStringLiteral("clearMeasurements"), tr("&Clear Measurements")),
            &QAction::triggered, this, &MeasureTools::clear);
}

void MeasureTools::setFreeBodyShown(bool on) {
    if (on == freeBodyShown_) return;
    freeBodyShown_ = on;
    emit freeBodyShownChanged(on);
    refresh();
}

std::optional<FreeBody> MeasureTools::freeBody() const {
    for (const QString& id : document_.selection())
        if (std::optional<FreeBody> body = freeBodyOf(document_.world(), id.toStdString()))
            return body;
    return std::nullopt;
}

// ---- the instruments ----------------------------------------------------------------------

std::optional<MeasureTools::End> MeasureTools::parseEnd(const QString& text) const {
    const QString t = text.trimmed();
    if (findProbeObject(document_.world(), t.toStdString())) return End{t, {}};
    // The probes' own reading of X:Y, so an end means what its probe means.
    const std::optional<Vec2> point = parseProbePoint(t.toStdString());
    if (!point) return std::nullopt;
    return End{{}, QPointF(point->x(), point->y())};
}

void MeasureTools::addRuler(const End& a, const End& b) {
    rulers_.push_back({{a, b}});
    refresh();
}

void MeasureTools::addProtractor(const End& a, const End& vertex, const End& c) {
    protractors_.push_back({{a, vertex, c}});
    refresh();
}

bool MeasureTools::addRuler(const QString& ends, QString* error) {
    const QStringList parts = splitEnds(ends);
    std::optional<End> a, b;
    if (parts.size() == 2) a = parseEnd(parts[0]), b = parseEnd(parts[1]);
    if (!a || !b) {
        if (error)
            *error = tr("--ruler \"%1\": expected A,B with each an object id or X:Y").arg(ends);
        return false;
    }
    addRuler(*a, *b);
    return true;
}

bool MeasureTools::addProtractor(const QString& ends, QString* error) {
    const QStringList parts = splitEnds(ends);
    std::optional<End> e[3];
    if (parts.size() == 3)
        for (int k = 0; k < 3; ++k) e[k] = parseEnd(parts[k]);
    if (!e[0] || !e[1] || !e[2]) {
        if (error)
            *error = tr("--protractor \"%1\": expected A,B,C (the vertex B in the middle, as in "
                        "angle(A,B,C)) with each an object id or X:Y")
                         .arg(ends);
        return false;
    }
    addProtractor(*e[0], *e[1], *e[2]);
    return true;
}

void MeasureTools::clear() {
    cancelGesture();
    rulers_.clear();
    protractors_.clear();
    select(Kind::None, -1);
    refresh();
}

bool MeasureTools::removeSelected() {
    // An end being dragged belongs to the selected instrument: the drag ends with it.
    if (gesture_ == Gesture::MoveEnd) gesture_ = Gesture::None;
    if (selectedKind_ == Kind::Ruler && selectedIndex_ < rulers_.size())
        rulers_.removeAt(selectedIndex_);
    else if (selectedKind_ == Kind::Protractor && selectedIndex_ < protractors_.size())
        protractors_.removeAt(selectedIndex_);
    else
        return false;
    select(Kind::None, -1);
    refresh();
    return true;
}

void MeasureTools::select(Kind kind, int index) {
    selectedKind_ = kind;
    selectedIndex_ = index;
}

bool MeasureTools::exists(const End& end) const {
    return end.object.isEmpty() || findProbeObject(document_.world(), end.object.toStdString());
}

QPointF MeasureTools::position(const End& end) const {
    if (end.object.isEmpty()) return end.point;
    const World& world = document_.world();
    const std::optional<ProbeObject> o = findProbeObject(world, end.object.toStdString());
    if (!o) return end.point;
    const Vec2 p = probeObjectPosition(world, *o);
    return {p.x(), p.y()};
}

void MeasureTools::dropOrphans() {
    const auto orphan = [this](const auto& instrument) {
        return std::any_of(std::begin(instrument.ends), std::end(instrument.ends),
                           [this](const End& e) { return !exists(e); });
    };
    if (gesture_ == Gesture::MoveEnd) cancelGesture();  // its index may go
    const qsizetype before = rulers_.size() + protractors_.size();
    rulers_.removeIf(orphan);
    protractors_.removeIf(orphan);
    if (rulers_.size() + protractors_.size() != before) select(Kind::None, -1);
    if (gesture_ != Gesture::None && std::any_of(std::begin(pending_), std::end(pending_),
                                                 [this](const End& e) { return !exists(e); }))
        cancelGesture();
}

QPointF MeasureTools::rulerEnd(int ruler, int end) const {
    return position(rulers_[ruler].ends[end]);
}

double MeasureTools::rulerLength(int ruler) const {
    return readProbe(rulerProbe(ruler));
}

QString MeasureTools::rulerText(QPointF a, QPointF b) const {
    const QPointF d = b - a;
    return tr("%1 m\ndx %2  dy %3")
        .arg(ui::shownNumber((vec(b) - vec(a)).norm(), 'f', 3), ui::shownNumber(d.x(), 'f', 3),
             ui::shownNumber(d.y(), 'f', 3));
}

QString MeasureTools::rulerLabel(int ruler) const {
    return rulerText(rulerEnd(ruler, 0), rulerEnd(ruler, 1));
}

double MeasureTools::protractorDegrees(int protractor) const {
    return std::abs(readProbe(protractorProbe(protractor))) * 180.0 / std::numbers::pi;
}

QString MeasureTools::protractorText(QPointF a, QPointF vertex, QPointF c) const {
    const double degrees =
        std::abs(signedAngle(vec(a), vec(vertex), vec(c))) * 180.0 / std::numbers::pi;
    return tr("%1°").arg(ui::shownNumber(degrees, 'f', 1));
}

QString MeasureTools::protractorLabel(int protractor) const {
    const Protractor& p = protractors_[protractor];
    return protractorText(position(p.ends[0]), position(p.ends[1]), position(p.ends[2]));
}

QString MeasureTools::probeArgument(const End& end) {
    if (!end.object.isEmpty()) return end.object;
    const auto number = [](double v) {
        return QString::number(v, 'g', QLocale::FloatingPointShortest);
    };
    return number(end.point.x()) + QLatin1Char(':') + number(end.point.y());
}

QString MeasureTools::rulerProbe(int ruler) const {
    const Ruler& r = rulers_[ruler];
    return QStringLiteral("distance(%1,%2)")
        .arg(probeArgument(r.ends[0]), probeArgument(r.ends[1]));
}

QString MeasureTools::protractorProbe(int protractor) const {
    const Protractor& p = protractors_[protractor];
    return QStringLiteral("angle(%1,%2,%3)")
        .arg(probeArgument(p.ends[0]), probeArgument(p.ends[1]), probeArgument(p.ends[2]));
}

QStringList MeasureTools::probes() const {
    QStringList texts;
    for (int i = 0; i < rulers_.size(); ++i) texts << rulerProbe(i);
    for (int i = 0; i < protractors_.size(); ++i) texts << protractorProbe(i);
    return texts;
}

double MeasureTools::readProbe(const QString& text) const {
    const World& world = document_.world();
    const ProbeParse parsed = parseProbe(world, text.toStdString());
    return parsed ? evaluateProbe(world, *parsed.probe) : 0.0;
}

// ---- drawing ------------------------------------------------------------------------------

void MeasureTools::refresh() {
    ui::MeasureOverlay overlay;
    for (int i = 0; i < rulers_.size(); ++i) {
        const Ruler& r = rulers_[i];
        const QPointF a = position(r.ends[0]), b = position(r.ends[1]);
        overlay.rulers.push_back({a, b, !r.ends[0].object.isEmpty(), !r.ends[1].object.isEmpty(),
                                  rulerText(a, b),
                                  selectedKind_ == Kind::Ruler && selectedIndex_ == i, false});
    }
    for (int i = 0; i < protractors_.size(); ++i) {
        const Protractor& p = protractors_[i];
        ui::MeasureOverlay::Protractor drawn;
        drawn.armA = position(p.ends[0]);
        drawn.vertex = position(p.ends[1]);
        drawn.armB = position(p.ends[2]);
        for (int k = 0; k < 3; ++k) drawn.attached[k] = !p.ends[k].object.isEmpty();
        drawn.label = protractorText(drawn.armA, drawn.vertex, *drawn.armB);
        drawn.selected = selectedKind_ == Kind::Protractor && selectedIndex_ == i;
        overlay.protractors.push_back(drawn);
    }
    if (gesture_ == Gesture::Ruler) {
        const QPointF a = position(pending_[0]), b = position(pending_[1]);
        overlay.rulers.push_back({a, b, !pending_[0].object.isEmpty(),
                                  !pending_[1].object.isEmpty(), rulerText(a, b), false, true});
    } else if (gesture_ != Gesture::None) {
        ui::MeasureOverlay::Protractor drawn;
        drawn.armA = position(pending_[0]);
        drawn.vertex = position(pending_[1]);
        const int arms = gesture_ == Gesture::ProtractorSecondArm ? 3 : 2;
        if (arms == 3) {
            drawn.armB = position(pending_[2]);
            drawn.label = protractorText(drawn.armA, drawn.vertex, *drawn.armB);
        }
        for (int k = 0; k < arms; ++k) drawn.attached[k] = !pending_[k].object.isEmpty();
        drawn.pending = true;
        overlay.protractors.push_back(drawn);
    }
    if (freeBodyShown_) {
        overlay.freeBodyShown = true;
        overlay.freeBody = freeBody();
        if (overlay.freeBody) {
            const ProbeObject& o = overlay.freeBody->body;
            const World& world = document_.world();
            overlay.freeBodyName = QString::fromStdString(o.rigid ? world.rigidBodies()[o.index].id
                                                                  : world.particles()[o.index].id);
        }
        const SystemMotion system = systemMotion(document_.world());
        if (const std::optional<Vec2> com = system.centreOfMass())
            overlay.centreOfMass = QPointF(com->x(), com->y());
        overlay.systemMomentum = QPointF(system.momentum.x(), system.momentum.y());
    }
    if (const QStringList now = probes(); now != probes_) {
        probes_ = now;
        emit probesChanged();
    }
    // Nothing shown before or now: no repaint for it (this runs after every step).
    if (overlay.isEmpty() && view_.measurements().isEmpty()) return;
    view_.setMeasurements(overlay);
}

// ---- the mouse and the keys ---------------------------------------------------------------

MeasureTools::End MeasureTools::snap(QPointF world) const {
    const ui::PickResult hit = view_.pick(view_.toWidget(world));
    if (hit.kind == ui::PickResult::Particle || hit.kind == ui::PickResult::Box)
        return {QString::fromStdString(hit.id), world};
    return {{}, world};
}

std::pair<MeasureTools::Kind, int> MeasureTools::instrumentAt(QPointF world) const {
    const QPointF p = view_.toWidget(world);
    const auto near = [&](const End& a, const End& b) {
        return segmentPixels(p, view_.toWidget(position(a)), view_.toWidget(position(b))) <=
               kPickPixels;
    };
    for (int i = static_cast<int>(rulers_.size()) - 1; i >= 0; --i)
        if (near(rulers_[i].ends[0], rulers_[i].ends[1])) return {Kind::Ruler, i};
    for (int i = static_cast<int>(protractors_.size()) - 1; i >= 0; --i) {
        const Protractor& r = protractors_[i];
        if (near(r.ends[0], r.ends[1]) || near(r.ends[0], r.ends[2])) return {Kind::Protractor, i};
    }
    return {Kind::None, -1};
}

MeasureTools::EndRef MeasureTools::endAt(QPointF world) const {
    const QPointF p = view_.toWidget(world);
    EndRef best;
    double nearest = kEndPickPixels;
    const auto consider = [&](Kind kind, int index, int end, const End& e) {
        const double d = QLineF(p, view_.toWidget(position(e))).length();
        if (d <= nearest) {
            nearest = d;
            best = {kind, index, end};
        }
    };
    for (int i = 0; i < rulers_.size(); ++i)
        for (int k = 0; k < 2; ++k) consider(Kind::Ruler, i, k, rulers_[i].ends[k]);
    for (int i = 0; i < protractors_.size(); ++i)
        for (int k = 0; k < 3; ++k) consider(Kind::Protractor, i, k, protractors_[i].ends[k]);
    return best;
}

MeasureTools::End& MeasureTools::endOf(const EndRef& ref) {
    return ref.kind == Kind::Ruler ? rulers_[ref.index].ends[ref.end]
                                   : protractors_[ref.index].ends[ref.end];
}

void MeasureTools::pressed(QPointF world, Qt::MouseButton button) {
    if (button != Qt::LeftButton) return;
    const CanvasTools::Tool tool = tools_.tool();
    if (gesture_ == Gesture::ProtractorSecondArm) {
        pending_[2] = snap(world);
        gesture_ = Gesture::None;
        // The new one is selected: Esc or Delete takes it back.
        select(Kind::Protractor, protractorCount());
        addProtractor(pending_[0], pending_[1], pending_[2]);  // A, the vertex B, C
        emit message(tr("Angle %1").arg(protractorLabel(protractorCount() - 1)));
        return;
    }
    const auto [kind, index] = instrumentAt(world);
    if (tool == CanvasTools::Tool::Select) {
        // A click on an instrument (not on an object) selects it; any other click lets it go.
        const bool onObject = static_cast<bool>(view_.pick(view_.toWidget(world)));
        select(onObject ? Kind::None : kind, onObject ? -1 : index);
        refresh();
        return;
    }
    if (tool != CanvasTools::Tool::Ruler && tool != CanvasTools::Tool::Protractor) return;
    if (const EndRef end = endAt(world); end.kind != Kind::None) {
        moving_ = end;
        movedFrom_ = endOf(end);
        pressedAt_ = world;
        gesture_ = Gesture::MoveEnd;
        select(end.kind, end.index);
        refresh();
        return;
    }
    if (kind != Kind::None) {
        select(kind, index);
        refresh();
        return;
    }
    pending_[0] = pending_[1] = pending_[2] = snap(world);
    pressedAt_ = world;
    gesture_ = tool == CanvasTools::Tool::Ruler ? Gesture::Ruler : Gesture::ProtractorFirstArm;
    refresh();
}

void MeasureTools::moved(QPointF world, Qt::MouseButtons buttons) {
    if (gesture_ == Gesture::MoveEnd && (buttons & Qt::LeftButton)) {
        endOf(moving_) = snap(world);
    } else if (gesture_ == Gesture::ProtractorSecondArm) {
        pending_[2] = snap(world);
    } else if (gesture_ == Gesture::Ruler && (buttons & Qt::LeftButton)) {
        pending_[1] = snap(world);
    } else if (gesture_ == Gesture::ProtractorFirstArm && (buttons & Qt::LeftButton)) {
        pending_[0] = snap(world);  // the vertex, pressed first, is pending_[1]: ∠ABC's B
    } else {
        return;
    }
    refresh();
}

void MeasureTools::released(QPointF world, Qt::MouseButton button) {
    if (button == Qt::LeftButton && gesture_ == Gesture::MoveEnd) {
        // A click on an end only selects its instrument.
        if (QLineF(view_.toWidget(pressedAt_), view_.toWidget(world)).length() >=
            CanvasTools::kClickPixels)
            endOf(moving_) = snap(world);
        gesture_ = Gesture::None;
        refresh();
        return;
    }
    if (button != Qt::LeftButton ||
        (gesture_ != Gesture::Ruler && gesture_ != Gesture::ProtractorFirstArm))
        return;
    const bool click = QLineF(view_.toWidget(pressedAt_), view_.toWidget(world)).length() <
                       CanvasTools::kClickPixels;
    if (click) {
        const bool ruler = gesture_ == Gesture::Ruler;
        cancelGesture();
        refresh();
        emit message(ruler ? tr("Drag from one point to the other to measure.")
                           : tr("Drag from the vertex along the first arm."));
        return;
    }
    if (gesture_ == Gesture::Ruler) {
        pending_[1] = snap(world);
        gesture_ = Gesture::None;
        select(Kind::Ruler, rulerCount());
        addRuler(pending_[0], pending_[1]);
        emit message(tr("Distance %1").arg(rulerLabel(rulerCount() - 1).replace('\n', ", ")));
        return;
    }
    pending_[0] = pending_[2] = snap(world);
    gesture_ = Gesture::ProtractorSecondArm;
    refresh();
    emit message(tr("Now click the second arm (Esc cancels)."));
}

void MeasureTools::cancelGesture() {
    if (gesture_ == Gesture::MoveEnd) endOf(moving_) = movedFrom_;
    gesture_ = Gesture::None;
}

bool MeasureTools::eventFilter(QObject* watched, QEvent* event) {
    const bool key = event->type() == QEvent::KeyPress || event->type() == QEvent::ShortcutOverride;
    if (watched != &view_ || !key) return Presenter::eventFilter(watched, event);
    const int k = static_cast<QKeyEvent*>(event)->key();
    const bool escape = k == Qt::Key_Escape;
    const bool remove = escape || k == Qt::Key_Delete || k == Qt::Key_Backspace;
    const bool handled =
        (escape && gesture_ != Gesture::None) || (remove && selectedKind_ != Kind::None);
    if (!handled) return Presenter::eventFilter(watched, event);
    // ShortcutOverride: the canvas takes the key from the window's Delete (the objects).
    event->accept();
    if (event->type() == QEvent::KeyPress) {
        if (escape && gesture_ != Gesture::None) {
            cancelGesture();
            refresh();
        } else {
            removeSelected();
        }
    }
    return true;
}

}  // namespace phasebox
