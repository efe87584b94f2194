#include "app/desktop/presenters/CanvasPresenter.h"

#include "app/desktop/CanvasTools.h"
#include "app/document/Document.h"
#include "app/io/OutputFile.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/BuildWorld.h"
#include "physics/scene/SceneDesc.h"
#include "physics/scene/SceneSchema.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"

#include <QAction>
#include <QActionGroup>
#include <QBuffer>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLocale>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace phasebox {

CanvasPresenter::CanvasPresenter(ui::SceneView& view, CanvasTools& tools, Document& document,
                                 SimulationController& controller, QObject* parent)
    : Presenter(parent), view_(view), tools_(tools), document_(document) {
    connect(&document_, &Document::sceneReset, this, [this] {
        view_.setWorld(&document_.world());
        view_.trails().clear();
        view_.fitToWorld(32.0, motionExtent());
        refresh();
    });
    connect(&document_, &Document::sceneEdited, this, [this] {
        view_.setWorld(&document_.world());
        refresh();
    });
    connect(&document_, &Document::simulationSettingsChanged, this, &CanvasPresenter::refresh);
    connect(&document_, &Document::selectionChanged, this, &CanvasPresenter::showSelection);
    connect(&controller, &SimulationController::stepped, this, &CanvasPresenter::refresh);
    connect(&tools_, &CanvasTools::message, this, &Presenter::message);
    connectKeyboard();
}

void CanvasPresenter::connectKeyboard() {
    const auto updateTargets = [this] {
        QStringList ids;
        for (const std::string& id : objectIds(document_.setup()))
            ids << QString::fromStdString(id);
        view_.setKeyboardTargets(ids);
    };
    connect(&document_, &Document::sceneReset, this, updateTargets);
    connect(&document_, &Document::sceneEdited, this, updateTargets);
    connect(&view_, &ui::SceneView::keyboardSelected, this,
            [this](const QString& id) { document_.setSelection({id}); });
    connect(&view_, &ui::SceneView::keyboardNudged, &tools_, &CanvasTools::nudgeSelection);
    connect(&view_, &ui::SceneView::keyboardActivated, this, [this](QPointF cursor) {
        if (tools_.tool() != CanvasTools::Tool::Select)
            tools_.placeAt(cursor);
        else if (!document_.selection().isEmpty())
            emit propertiesWanted();
    });
    connect(&tools_, &CanvasTools::toolChanged, this, [this](CanvasTools::Tool tool) {
        view_.setArrowsMoveSelection(tool == CanvasTools::Tool::Select);
    });
}

QString CanvasPresenter::describeSelection() const {
    const QStringList selection = document_.selection();
    if (selection.isEmpty())
        return tr(
            "Nothing selected. Tab walks the objects; with a drawing tool, the arrow keys "
            "move the cursor and Enter places the object there.");
    const SceneDesc& setup = document_.setup();
    const ObjectRef ref = findObject(setup, selection.first().toStdString());
    QString text = tr("Selected: %1 %2.").arg(objectKindName(ref.kind), selection.first());
    const World& world = document_.world();
    const std::string id = selection.first().toStdString();
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
        if (world.particles()[static_cast<std::size_t>(i)].id == id) {
            const Vec2 x = world.particlePosition(i), v = world.particleVelocity(i);
            text += QLatin1Char(' ') +
                    tr("Position %1, %2 m; velocity %3, %4 m/s.")
                        .arg(QLocale().toString(x.x(), 'f', 2), QLocale().toString(x.y(), 'f', 2),
                             QLocale().toString(v.x(), 'f', 2), QLocale().toString(v.y(), 'f', 2));
        }
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
        if (world.rigidBodies()[static_cast<std::size_t>(i)].id == id) {
            const Vec2 x = world.bodyPosition(i), v = world.bodyVelocity(i);
            text += QLatin1Char(' ') +
                    tr("Position %1, %2 m; velocity %3, %4 m/s.")
                        .arg(QLocale().toString(x.x(), 'f', 2), QLocale().toString(x.y(), 'f', 2),
                             QLocale().toString(v.x(), 'f', 2), QLocale().toString(v.y(), 'f', 2));
        }
    return text + QLatin1Char(' ') +
           tr("Arrows move it (Shift: finely), Enter opens its properties.");
}

void CanvasPresenter::createActions(QWidget& window) {
    auto* group = new QActionGroup(this);
    static const char* const names[] = {
        "toolSelect",  "toolParticle", "toolSpring", "toolCloth", "toolBox",   "toolDisk",
        "toolPolygon", "toolPlane",    "toolPin",    "toolJoint", "toolRuler", "toolProtractor"};
    // The drawing tools on the digits, the measuring ones on their initials.
    static const int keys[] = {Qt::Key_1, Qt::Key_2, Qt::Key_3, Qt::Key_4, Qt::Key_5, Qt::Key_6,
                               Qt::Key_7, Qt::Key_8, Qt::Key_9, Qt::Key_0, Qt::Key_R, Qt::Key_P};
    static_assert(std::size(names) == std::size(keys));
    for (int i = 0; i < static_cast<int>(std::size(names)); ++i) {  // CanvasTools::Tool's order
        const auto tool = static_cast<CanvasTools::Tool>(i);
        const QKeySequence key(keys[i]);
        QAction* a = addWindowAction(window, names[i], CanvasTools::toolName(tool), key);
        connect(a, &QAction::triggered, this, [this, tool] { tools_.setTool(tool); });
        a->setCheckable(true);
        a->setToolTip(CanvasTools::toolName(tool) + QStringLiteral(" (") + key.toString() +
                      QStringLiteral("): ") + CanvasTools::toolHelp(tool));
        a->setChecked(tool == CanvasTools::Tool::Select);
        group->addAction(a);
    }
    toolActions_ = group->actions();
    auto* sides = new QSpinBox(&window);
    sides->setObjectName(QStringLiteral("polygonSides"));
    sides->setRange(3, SceneLimits::kMaxPolygonVertices);
    sides->setValue(tools_.polygonSides());
    sides->setSuffix(tr(" sides"));
    sides->setToolTip(tr("Sides of the regular polygon the Add polygon tool draws"));
    connect(sides, &QSpinBox::valueChanged, this, [this](int n) {
        tools_.setPolygonSides(n);
        tools_.setTool(CanvasTools::Tool::Polygon);
    });
    polygonSides_ = sides;
    auto* joints = new QComboBox(&window);
    joints->setObjectName(QStringLiteral("jointType"));
    for (const auto& [type, name] :
         {std::pair{JointType::Hinge, tr("hinge")}, std::pair{JointType::Rod, tr("rod")},
          std::pair{JointType::Rope, tr("rope")}, std::pair{JointType::Weld, tr("weld")},
          std::pair{JointType::Pulley, tr("pulley")}, std::pair{JointType::Track, tr("track")}})
        joints->addItem(name, static_cast<int>(type));
    joints->setToolTip(tr("The kind of joint the Add joint tool makes"));
    connect(joints, &QComboBox::currentIndexChanged, this, [this, joints](int) {
        tools_.setJointType(static_cast<JointType>(joints->currentData().toInt()));
        tools_.setTool(CanvasTools::Tool::Joint);
    });
    jointType_ = joints;
    connect(&tools_, &CanvasTools::toolChanged, this, [this](CanvasTools::Tool tool) {
        toolActions_[static_cast<int>(tool)]->setChecked(true);
    });

    connect(addWindowAction(window, "fit", tr("&Fit Scene"), Qt::Key_F), &QAction::triggered, this,
            [this] { view_.fitToWorld(); });
    QAction* follow = addWindowAction(window, "follow", tr("F&ollow"), Qt::SHIFT | Qt::Key_F);
    follow->setCheckable(true);
    follow->setToolTip(tr("Keep the selection, or every moving object, in view while it runs"));
    connect(follow, &QAction::toggled, this, [this](bool on) {
        following_ = on;
        if (on) followNow();
    });
    connect(addWindowAction(window, "exportCanvas", tr("Export &Canvas as PNG…")),
            &QAction::triggered, this, &CanvasPresenter::exportInteractively);
    using O = ui::RenderOptions;
    for (const auto& [name, text, key, member, settingsKey] :
         {std::tuple{"trails", tr("&Trails"), Qt::Key_T, &O::trails, "view/trails"},
          std::tuple{"velocityArrows", tr("&Velocity Arrows"), Qt::Key_V, &O::velocityArrows,
                     "view/velocityArrows"},
          std::tuple{"forceArrows", tr("&Force Arrows (springs, joints)"), Qt::Key_A,
                     &O::forceArrows, "view/forceArrows"},
          std::tuple{"labels", tr("Object &Labels"), Qt::Key_L, &O::labels, "view/labels"},
          std::tuple{"grid", tr("Metre &Grid"), Qt::Key_G, &O::grid, ""}}) {
        QAction* a = addWindowAction(window, name, text, key);
        a->setCheckable(true);
        a->setChecked(view_.renderOptions().*member);
        connect(a, &QAction::toggled, this,
                [this, member = member](bool on) { setOption(member, on); });
        options_.push_back({a, member, QString::fromLatin1(settingsKey)});
    }
}

void CanvasPresenter::setOption(bool ui::RenderOptions::*member, bool on) {
    ui::RenderOptions options = view_.renderOptions();
    options.*member = on;
    view_.setRenderOptions(options);
    if (member == &ui::RenderOptions::trails) view_.trails().clear();
}

void CanvasPresenter::readSettings(const QSettings& settings) {
    for (const ViewOption& option : options_)
        if (!option.settingsKey.isEmpty())
            option.action->setChecked(settings.value(option.settingsKey, false).toBool());
}

void CanvasPresenter::writeSettings(QSettings& settings) const {
    for (const ViewOption& option : options_)
        if (!option.settingsKey.isEmpty())
            settings.setValue(option.settingsKey, view_.renderOptions().*option.member);
}

void CanvasPresenter::setPresentation(bool on) {
    presentation_ = on;
    ui::RenderOptions options = view_.renderOptions();
    for (const ViewOption& option : options_)
        if (option.member == &ui::RenderOptions::labels)
            options.labels = on || option.action->isChecked();
    view_.setRenderOptions(options);
    applyLook();
}

void CanvasPresenter::setAppearance(const ui::Appearance& appearance) {
    appearance_ = appearance;
    applyLook();
}

void CanvasPresenter::applyLook() {
    ui::RenderOptions options = view_.renderOptions();
    options.lineWidthScale = (presentation_ ? 2.0 : 1.0) * appearance_.lineScale;
    options.fontScale = (presentation_ ? 1.8 : 1.0) * appearance_.textScale;
    options.colors = ui::sceneColors(appearance_.highContrast);
    options.background = ui::canvasBackground(appearance_.highContrast);
    view_.setRenderOptions(options);
}

QRectF CanvasPresenter::motionExtent() const {
    // Where the scene's moving objects go over its duration, from a copy of it run ahead for at
    // most kPreviewSeconds of wall time, so that an example opens with a view that holds its
    // motion (a projectile's whole arc, not its launch pad). A run that starts to diverge is
    // not followed past that point.
    BuildResult built;
    try {
        built = buildWorld(document_.setup());
    } catch (const SceneError&) {
        return {};
    }
    World& world = *built.world;
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    const auto sample = [&] {
        for (int i = 0; i < static_cast<int>(world.particles().size()); ++i)
            if (!world.particles()[i].pinned)
                for (int k = 0; k < 2; ++k) {
                    lo[k] = std::min(lo[k], world.particlePosition(i)[k]);
                    hi[k] = std::max(hi[k], world.particlePosition(i)[k]);
                }
        for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i)
            if (!world.rigidBodies()[i].isStatic)
                for (int k = 0; k < 2; ++k) {
                    const double reach = 0.5 * world.rigidBodies()[i].size.norm();
                    lo[k] = std::min(lo[k], world.bodyPosition(i)[k] - reach);
                    hi[k] = std::max(hi[k], world.bodyPosition(i)[k] + reach);
                }
    };
    QElapsedTimer clock;
    clock.start();
    const double duration = document_.setup().simulation.duration;
    while (world.time() < duration && clock.elapsed() < kPreviewMilliseconds) {
        if (!world.step() || std::abs(world.energy().drift) > world.divergenceScale()) break;
        sample();
    }
    if (!(lo[0] <= hi[0])) return {};
    return QRectF(QPointF(lo[0], lo[1]), QPointF(hi[0], hi[1]));
}

void CanvasPresenter::followNow() {
    // The selected objects' positions, or every dynamic body's when nothing is selected.
    const World& world = document_.world();
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    const auto include = [&](const Vec2& p, double reach) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], p[k] - reach);
            hi[k] = std::max(hi[k], p[k] + reach);
        }
    };
    const QStringList& selection = document_.selection();
    const auto wanted = [&](const std::string& id, bool dynamic) {
        return selection.isEmpty() ? dynamic : selection.contains(QString::fromStdString(id));
    };
    for (int i = 0; i < static_cast<int>(world.particles().size()); ++i) {
        const Particle& p = world.particles()[i];
        if (wanted(p.id, !p.pinned)) include(world.particlePosition(i), p.radius);
    }
    for (int i = 0; i < static_cast<int>(world.rigidBodies().size()); ++i) {
        const RigidBody& b = world.rigidBodies()[i];
        if (wanted(b.id, !b.isStatic)) include(world.bodyPosition(i), 0.5 * b.size.norm());
    }
    if (!(lo[0] <= hi[0])) return;
    ui::ViewTransform v = view_.view();
    if (v.keepInView(QRectF(QPointF(lo[0], lo[1]), QPointF(hi[0], hi[1])), kFollowMargin))
        view_.setView(v);
}

void CanvasPresenter::refresh() {
    if (following_) followNow();
    tools_.refreshGrabOverlay();
    const SimulationDesc& s = document_.setup().simulation;
    view_.setHudText(tr("t = %L1 s   %2, dt %L3 s")
                         .arg(document_.world().time(), 0, 'f', 2)
                         .arg(QString::fromStdString(s.integrator))
                         .arg(s.dt, 0, 'g', 4));
    view_.setAccessibleDescription(describeSelection());
    view_.update();
}

void CanvasPresenter::showSelection() {
    ui::RenderOptions options = view_.renderOptions();
    options.selectedIds.clear();
    for (const QString& id : document_.selection()) options.selectedIds.insert(id.toStdString());
    view_.setRenderOptions(options);
    view_.setAccessibleDescription(describeSelection());
}

bool CanvasPresenter::exportPicture(const QString& path, QString* error) const {
    if (!document_.mayWriteOutput(path, error)) return false;
    const QImage image = view_.renderImage(view_.size().expandedTo(QSize(800, 600)));
    QBuffer png;
    png.open(QIODevice::WriteOnly);
    if (!image.save(&png, "PNG")) {
        if (error) *error = tr("%1: cannot draw the picture").arg(path);
        return false;
    }
    return OutputFile::writeAll(path, png.data(), error, tr("the picture"));
}

void CanvasPresenter::exportInteractively() {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const QString path = QFileDialog::getSaveFileName(
        view_.window(), tr("Export Canvas"), QDir(dir).filePath(QStringLiteral("scene.png")),
        tr("PNG (*.png)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportPicture(path, &error))
        QMessageBox::warning(view_.window(), tr("Export failed"), error);
}

}  // namespace phasebox
