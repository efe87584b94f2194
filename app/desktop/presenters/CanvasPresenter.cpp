#include "app/desktop/presenters/CanvasPresenter.h"

#include "app/desktop/CanvasTools.h"
#include "app/document/Document.h"
#include "app/sim/SimulationController.h"
#include "physics/scene/SceneDesc.h"
#include "physics/scene/SceneSchema.h"
#include "physics/world/World.h"
#include "ui/canvas/SceneView.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>

#include <tuple>

namespace phasebox {

CanvasPresenter::CanvasPresenter(ui::SceneView& view, CanvasTools& tools, Document& document,
                                 SimulationController& controller, QObject* parent)
    : Presenter(parent), view_(view), tools_(tools), document_(document) {
    connect(&document_, &Document::sceneReset, this, [this] {
        view_.setWorld(&document_.world());
        view_.trails().clear();
        view_.fitToWorld();
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
}

void CanvasPresenter::createActions(QWidget& window) {
    auto* group = new QActionGroup(this);
    static const char* const names[] = {"toolSelect", "toolParticle", "toolSpring",  "toolCloth",
                                        "toolBox",    "toolDisk",     "toolPolygon", "toolPlane",
                                        "toolPin",    "toolJoint"};
    for (int i = 0; i < static_cast<int>(std::size(names)); ++i) {  // CanvasTools::Tool's order
        const auto tool = static_cast<CanvasTools::Tool>(i);
        const QKeySequence key(i < 9 ? Qt::Key_1 + i : Qt::Key_0);
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
    for (const JointType type : {JointType::Hinge, JointType::Rod, JointType::Rope, JointType::Weld,
                                 JointType::Pulley, JointType::Track})
        joints->addItem(QString::fromUtf8(schema::kJointTypeNames[static_cast<int>(type)].data()),
                        static_cast<int>(type));
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
    ui::RenderOptions options = view_.renderOptions();
    options.lineWidthScale = on ? 2.0 : 1.0;
    options.fontScale = on ? 1.8 : 1.0;
    for (const ViewOption& option : options_)
        if (option.member == &ui::RenderOptions::labels)
            options.labels = on || option.action->isChecked();
    view_.setRenderOptions(options);
}

void CanvasPresenter::refresh() {
    tools_.refreshGrabOverlay();
    const SimulationDesc& s = document_.setup().simulation;
    view_.setHudText(tr("t = %1 s   %2, dt %3 s")
                         .arg(document_.world().time(), 0, 'f', 2)
                         .arg(QString::fromStdString(s.integrator))
                         .arg(s.dt, 0, 'g', 4));
    view_.update();
}

void CanvasPresenter::showSelection() {
    ui::RenderOptions options = view_.renderOptions();
    options.selectedIds.clear();
    for (const QString& id : document_.selection()) options.selectedIds.insert(id.toStdString());
    view_.setRenderOptions(options);
}

bool CanvasPresenter::exportPicture(const QString& path, QString* error) const {
    const QImage image = view_.renderImage(view_.size().expandedTo(QSize(800, 600)));
    if (image.save(path, "PNG")) return true;
    if (error) *error = tr("could not write %1").arg(path);
    return false;
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
