// The dock panels as the user meets them: what they list, what they emit when used, what they
// keep quiet about when the app updates them. Run offscreen; also renders each panel to
// /tmp/panel_*.png for a look.

#include "physics/integrators/Integrator.h"
#include "physics/scene/ObjectKinds.h"
#include "ui/panels/EffectsPanel.h"
#include "ui/panels/ParametersPanel.h"
#include "ui/panels/PropertiesPanel.h"
#include "ui/panels/SceneBrowser.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>
#include <QTreeWidget>
#include <QWheelEvent>

using namespace phasebox;
using namespace phasebox::ui;

namespace {
QStringList registryNames() {
    QStringList names;
    for (const IntegratorInfo& info : integratorRegistry())
        names << QString::fromUtf8(info.name.data(), static_cast<qsizetype>(info.name.size()));
    return names;
}

// Types into a spin box as a user would: select the number, type, press Enter.
void typeInto(QAbstractSpinBox* box, const QString& text) {
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Enter);
}

QTreeWidgetItem* findItem(QTreeWidget* tree, const QString& text) {
    const auto items = tree->findItems(text, Qt::MatchExactly | Qt::MatchRecursive);
    return items.isEmpty() ? nullptr : items.first();
}

std::vector<EffectRow> sampleEffects() {
    return {{"gravity", true, true, 0.0021, {}},
            {"drag", true, true, 0.0104, {}},
            {"springs", true, false, 0.134, {}},
            {"contacts", true, false, 0.87, {}},
            {"integrator", true, false, 0.0456, {}}};
}

SceneDesc sampleScene() {
    SceneDesc scene;
    scene.particles.resize(2);  // the second keeps its default id, p1
    scene.particles[0].id = "ball";
    scene.particles[1].pinned = true;
    scene.boxes.resize(1);  // b0
    scene.boxes[0].size = {1.0, 0.5};
    scene.planes.resize(1);
    scene.planes[0].id = "ground";
    scene.springs.resize(1);  // s0
    scene.springs[0].a = "ball";
    scene.springs[0].anchor = Point2{0.0, 0.0};
    scene.springs[0].stiffness = 1e6;
    scene.cloths.resize(1);
    scene.cloths[0].id = "flag";
    scene.cloths[0].resolution = {20, 12};
    return scene;
}

std::vector<PropertyField> ballFields() {
    return {{"position.x", "Position &x", "m", 1.0, -1e6, 1e6, 3, false},
            {"position.y", "Position &y", "m", 0.0, -1e6, 1e6, 3, false},
            {"mass", "&Mass", "kg", 1.0, 1e-6, 1e9, 3, false},
            {"radius", "&Radius", "m", 0.05, 0.0, 100.0, 3, false},
            {"pinned", "&Pinned", "", 0.0, 0.0, 1.0, 0, true}};
}
}  // namespace

class TestPanels : public QObject {
    Q_OBJECT
private slots:
    // ---- ParametersPanel ---------------------------------------------------------------
    void integratorComboListsAllTen() {
        ParametersPanel panel;
        auto* combo = panel.findChild<QComboBox*>("integrator");
        QVERIFY(combo);
        QCOMPARE(combo->count(), 10);
        QStringList listed;
        for (int i = 0; i < combo->count(); ++i) {
            listed << combo->itemData(i).toString();
            const QString tip = combo->itemData(i, Qt::ToolTipRole).toString();
            QVERIFY2(tip.contains("order") && tip.contains("force evaluations"), qPrintable(tip));
        }
        QCOMPARE(listed, registryNames());
    }

    void comboEmitsIntegratorChanged() {
        ParametersPanel panel;
        QSignalSpy spy(&panel, &ParametersPanel::integratorChanged);
        auto* combo = panel.findChild<QComboBox*>("integrator");
        combo->setCurrentIndex(combo->findData("rk4"));
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QString("rk4"));
        QCOMPARE(panel.integrator(), QString("rk4"));
    }

    void setSimulationDoesNotEmit() {
        ParametersPanel panel;
        QSignalSpy integrator(&panel, &ParametersPanel::integratorChanged);
        QSignalSpy dt(&panel, &ParametersPanel::dtChanged);
        QSignalSpy substeps(&panel, &ParametersPanel::substepsChanged);
        QSignalSpy tolerance(&panel, &ParametersPanel::toleranceChanged);
        QSignalSpy newton(&panel, &ParametersPanel::newtonIterationsChanged);
        QSignalSpy speed(&panel, &ParametersPanel::speedChanged);
        SimulationDesc sim;
        sim.integrator = "implicit_euler";
        sim.dt = 1.0 / 240;
        sim.substeps = 8;
        sim.tolerance = 1e-9;
        sim.newtonIterations = 3;
        panel.setSimulation(sim);
        panel.setSpeed(0.25);
        for (QSignalSpy* spy : {&integrator, &dt, &substeps, &tolerance, &newton, &speed})
            QCOMPARE(spy->count(), 0);
        QCOMPARE(panel.integrator(), QString("implicit_euler"));
        QCOMPARE(panel.dt(), 1.0 / 240);  // exactly: the editor keeps the double it was given
        QCOMPARE(panel.substeps(), 8);
        QCOMPARE(panel.tolerance(), 1e-9);
        QCOMPARE(panel.newtonIterations(), 3);
        QCOMPARE(panel.speed(), 0.25);
    }

    void toleranceEnabledOnlyForAdaptive() {
        ParametersPanel panel;
        auto* combo = panel.findChild<QComboBox*>("integrator");
        auto* tolerance = panel.findChild<QAbstractSpinBox*>("tolerance");
        auto* newton = panel.findChild<QSpinBox*>("newtonIterations");
        for (const QString& name : registryNames()) {
            combo->setCurrentIndex(combo->findData(name));
            const bool adaptive = name == "adaptive_euler" || name == "rk45";
            QVERIFY2(tolerance->isEnabled() == adaptive, qPrintable(name));
            QVERIFY2(newton->isEnabled() == (name == "implicit_euler"), qPrintable(name));
        }
        SimulationDesc sim;
        sim.integrator = "rk45";
        panel.setSimulation(sim);  // the setter updates the enabled state too
        QVERIFY(tolerance->isEnabled());
    }

    void dtRefusesZeroAndAboveOne() {
        ParametersPanel panel;
        panel.show();
        auto* dt = panel.findChild<QDoubleSpinBox*>("dt");
        QCOMPARE(dt->minimum(), 1e-5);
        QCOMPARE(dt->maximum(), 1.0);
        QSignalSpy spy(&panel, &ParametersPanel::dtChanged);
        const double before = panel.dt();
        typeInto(dt, "0");
        QCOMPARE(panel.dt(), before);
        typeInto(dt, "1.5");
        QCOMPARE(panel.dt(), before);
        typeInto(dt, "-0.01");
        QCOMPARE(panel.dt(), before);
        QCOMPARE(spy.count(), 0);
        typeInto(dt, "2e-3");
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toDouble(), 0.002);
        dt->setValue(0.0);  // programmatic values are clamped into the range as well
        QCOMPARE(dt->value(), 1e-5);

        // The wheel over a field without focus does not change the integrator mid-run.
        QSignalSpy integrator(&panel, &ParametersPanel::integratorChanged);
        auto* combo = panel.findChild<QComboBox*>("integrator");
        QWheelEvent wheel(QPointF(5, 5), combo->mapToGlobal(QPointF(5, 5)), {}, {0, -120},
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(combo, &wheel);
        QCOMPARE(integrator.count(), 0);
    }

    void dtPresetsAndLogSteps() {
        ParametersPanel panel;
        QSignalSpy spy(&panel, &ParametersPanel::dtChanged);
        const auto actions = panel.findChild<QToolButton*>("dtPresets")->menu()->actions();
        QCOMPARE(actions.size(), 5);
        actions.at(2)->trigger();  // 1/120
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toDouble(), 1.0 / 120);
        panel.findChild<QDoubleSpinBox*>("dt")->stepBy(-1);  // halves
        QCOMPARE(panel.dt(), 1.0 / 240);
    }

    void speedAndTransport() {
        ParametersPanel panel;
        QSignalSpy speed(&panel, &ParametersPanel::speedChanged);
        auto* combo = panel.findChild<QComboBox*>("speed");
        QCOMPARE(combo->count(), 5);
        combo->setCurrentIndex(0);
        QCOMPARE(speed.count(), 1);
        QCOMPARE(speed.at(0).at(0).toDouble(), 0.25);
        panel.setSpeed(3.0);  // nearest on a log scale
        QCOMPARE(panel.speed(), 4.0);
        QCOMPARE(speed.count(), 1);

        QAction play("Play");
        play.setCheckable(true);
        play.setShortcut(QKeySequence(Qt::Key_Space));
        QAction step("Step");
        step.setShortcuts({QKeySequence(Qt::Key_S), QKeySequence(Qt::Key_Right)});
        panel.setActions(&play, &step, nullptr);
        auto* playButton = panel.findChild<QToolButton*>("play");
        QCOMPARE(playButton->defaultAction(), &play);
        QVERIFY(playButton->toolTip().contains("Space"));
        play.setText("Pause");  // the app relabels its action; the tooltip keeps the key
        QVERIFY(playButton->toolTip().contains("Pause") && playButton->toolTip().contains("Space"));
        QVERIFY(panel.findChild<QToolButton*>("step")->toolTip().contains("Right"));
        QVERIFY(!panel.findChild<QToolButton*>("reset")->isEnabled());

        panel.setAdvice("dt is past the stable limit", true);
        QVERIFY(panel.adviceText().contains("stable limit"));
        QVERIFY(panel.findChild<QLabel*>("advice")->property("warning").toBool());
    }

    // ---- EffectsPanel ------------------------------------------------------------------
    void effectRowsFollowSetEffects() {
        EffectsPanel panel;
        panel.setEffects(sampleEffects());
        QCOMPARE(panel.effectNames(),
                 QStringList({"gravity", "drag", "springs", "contacts", "integrator"}));
        auto* tree = panel.findChild<QTreeWidget*>("effects");
        QVERIFY(tree->topLevelItem(0)->flags() & Qt::ItemIsUserCheckable);
        QVERIFY(!(tree->topLevelItem(3)->flags() & Qt::ItemIsUserCheckable));
        QVERIFY(!tree->topLevelItem(3)->data(0, Qt::CheckStateRole).isValid());
        QCOMPARE(panel.costText("contacts"), QString("0.870 ms/step"));

        // Same names: updated in place, the selected row stays selected.
        QTreeWidgetItem* drag = tree->topLevelItem(1);
        drag->setSelected(true);
        auto rows = sampleEffects();
        rows[1].enabled = false;
        panel.setEffects(rows);
        QCOMPARE(tree->topLevelItem(1), drag);
        QVERIFY(drag->isSelected());
        QCOMPARE(drag->checkState(0), Qt::Unchecked);
        QCOMPARE(panel.costText("drag"), QString("–"));  // switched off costs nothing

        // Another set of rows: rebuilt, the selection kept by name.
        rows.insert(rows.begin(), EffectRow{"wind", true, true, 0.0, {}});
        panel.setEffects(rows);
        QCOMPARE(panel.effectNames().first(), QString("wind"));
        QCOMPARE(tree->selectedItems().size(), 1);
        QCOMPARE(tree->selectedItems().first()->data(0, Qt::UserRole).toString(), QString("drag"));
    }

    void togglingEmitsEffectToggled() {
        EffectsPanel panel;
        QSignalSpy spy(&panel, &EffectsPanel::effectToggled);
        panel.setEffects(sampleEffects());
        auto* tree = panel.findChild<QTreeWidget*>("effects");
        tree->topLevelItem(0)->setCheckState(0, Qt::Unchecked);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QString("gravity"));
        QCOMPARE(spy.at(0).at(1).toBool(), false);
        // Updates from the app are not toggles.
        panel.setEffects(sampleEffects());
        panel.setCost("gravity", 0.5);
        QCOMPARE(spy.count(), 1);
    }

    void addMenuListsOnlyAbsentEffects() {
        EffectsPanel panel;
        panel.setEffects(sampleEffects());
        QStringList offered;
        for (QAction* action : panel.addMenu()->actions()) offered << action->data().toString();
        QCOMPARE(offered, QStringList({"newtonian_gravity", "buoyancy", "wind", "flocking",
                                       "particle_collisions"}));
        QSignalSpy spy(&panel, &EffectsPanel::addEffectRequested);
        panel.addMenu()->actions().at(2)->trigger();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QString("wind"));

        std::vector<EffectRow> all;
        for (const QString& name : EffectsPanel::contractEffects())
            all.push_back({name, true, true, 0, {}});
        panel.setEffects(all);
        QVERIFY(panel.addMenu()->actions().isEmpty());
        QVERIFY(!panel.findChild<QToolButton*>("addEffect")->isEnabled());
    }

    // The step profile under the effects: one row per stage, in order, "–" for a stage that
    // has not run; a second profile updates the rows in place.
    void stageCostsShowTheStepProfile() {
        EffectsPanel panel;
        auto* stages = panel.findChild<QTreeWidget*>("stages");
        QVERIFY(stages);
        panel.setStageCosts({{"integrate", 0.5}, {"collide", -1.0}, {"solve contacts", 1.25}});
        QCOMPARE(stages->topLevelItemCount(), 3);
        QCOMPARE(stages->topLevelItem(2)->text(0), QString("Solve contacts"));
        QCOMPARE(panel.stageCostText("integrate"), QString("0.500 ms"));
        QCOMPARE(panel.stageCostText("collide"), QString("–"));
        QCOMPARE(panel.stageCostText("guard"), QString());
        QTreeWidgetItem* first = stages->topLevelItem(0);
        panel.setStageCosts({{"integrate", 0.02}, {"collide", 0.0}});
        QCOMPARE(stages->topLevelItem(0), first);
        QCOMPARE(stages->topLevelItemCount(), 2);
        QCOMPARE(panel.stageCostText("integrate"), QString("20.0 µs"));
    }

    void costsFromTheWorldProfile() {
        EffectsPanel panel;
        panel.setEffects(sampleEffects());
        // 1000 steps: gravity 2 ms in all, contacts 1 ms, the whole stepping 5 ms.
        const std::vector<EffectCost> costs{
            {"gravity", 0.002}, {"drag", 0.0005}, {"contacts", 0.001}};
        panel.setCosts(costs, 1000, 0.005);
        // Issue 37: each cost carries its unit, per step.
        QCOMPARE(panel.costText("gravity"), QString("2.00 µs/step"));
        QCOMPARE(panel.costText("springs"), QString("–"));  // not in the profile: not running
        QCOMPARE(panel.costText("integrator"), QString("1.50 µs/step"));
        QCOMPARE(panel.totalText(), QString("total: 5.00 µs per step"));
        QCOMPARE(EffectsPanel::formatMs(1.2), QString("1.20 ms"));
        QCOMPARE(EffectsPanel::formatMs(123.4), QString("123 ms"));
        QCOMPARE(EffectsPanel::formatMs(9.996), QString("10.0 ms"));
        QCOMPARE(EffectsPanel::formatMs(qQNaN()), QString("–"));
    }

    // ---- PropertiesPanel ---------------------------------------------------------------
    void propertiesEmptyState() {
        PropertiesPanel panel;
        QVERIFY(!panel.hasObject());
        QVERIFY(panel.findChild<QLabel*>("emptyHint")->text().contains("Select an object"));
        panel.setObject("ball", ballFields());
        QVERIFY(panel.hasObject());
        panel.clearObject();
        QVERIFY(!panel.hasObject());
    }

    void propertyEditedWithTypedValue() {
        PropertiesPanel panel;
        panel.setObject("Particle ball", ballFields());
        panel.show();
        QSignalSpy spy(&panel, &PropertiesPanel::propertyEdited);
        auto* mass = qobject_cast<QAbstractSpinBox*>(panel.editor("mass"));
        QVERIFY(mass);
        typeInto(mass, "2.5");
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QString("mass"));
        QCOMPARE(spy.at(0).at(1).toDouble(), 2.5);
        // Enter on text left as shown commits nothing new.
        typeInto(mass, QString());
        QCOMPARE(spy.count(), 1);

        auto* pinned = qobject_cast<QCheckBox*>(panel.editor("pinned"));
        QVERIFY(pinned);
        pinned->setFocus();
        QTest::keyClick(pinned, Qt::Key_Space);  // by keyboard, as the dock promises
        QCOMPARE(spy.count(), 2);
        QCOMPARE(spy.at(1).at(1).toDouble(), 1.0);
    }

    void stiffnessAcceptsScientificNotation() {
        PropertiesPanel panel;
        panel.setObject("Spring s0",
                        {{"stiffness", "&Stiffness", "N/m", 10.0, 1e-6, 1e12, 2, false}});
        panel.show();
        QSignalSpy spy(&panel, &PropertiesPanel::propertyEdited);
        auto* stiffness = qobject_cast<QDoubleSpinBox*>(panel.editor("stiffness"));
        typeInto(stiffness, "1e6");
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(1).toDouble(), 1e6);
        QCOMPARE(stiffness->text(), QString("1e6 N/m"));
        typeInto(stiffness, "2.5E7");
        QCOMPARE(spy.at(1).at(1).toDouble(), 2.5e7);
    }

    void errorsShowAndClear() {
        PropertiesPanel panel;
        panel.setObject("Particle ball", ballFields());
        panel.show();
        panel.showError("mass must be > 0");
        QCOMPARE(panel.errorText(), QString("mass must be > 0"));
        QVERIFY(panel.findChild<QLabel*>("error")->isVisible());

        // Out of range: refused, the spin box goes back, and the panel says why.
        QSignalSpy spy(&panel, &PropertiesPanel::propertyEdited);
        auto* mass = qobject_cast<QDoubleSpinBox*>(panel.editor("mass"));
        typeInto(mass, "-5");
        QCOMPARE(spy.count(), 0);
        QCOMPARE(mass->value(), 1.0);
        QVERIFY2(panel.errorText().contains("must be ≥"), qPrintable(panel.errorText()));

        typeInto(mass, "3");  // a good edit clears the message
        QCOMPARE(spy.count(), 1);
        QVERIFY(panel.errorText().isEmpty());
        QVERIFY(!panel.findChild<QLabel*>("error")->isVisible());
    }

    void updateValuesKeepsFormAndTyping() {
        PropertiesPanel panel;
        panel.setObject("Particle ball", ballFields());
        panel.show();
        panel.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&panel));
        QWidget* x = panel.editor("position.x");
        QWidget* y = panel.editor("position.y");
        auto fields = ballFields();
        fields[0].value = 2.0;
        fields[1].value = -3.25;
        panel.updateValues(fields);
        QCOMPARE(panel.editor("position.x"), x);  // not rebuilt
        QCOMPARE(qobject_cast<QDoubleSpinBox*>(x)->value(), 2.0);

        // The user is typing into y: a running update must not overwrite the typing.
        auto* ySpin = qobject_cast<QDoubleSpinBox*>(y);
        ySpin->setFocus();
        ySpin->selectAll();
        QTest::keyClicks(ySpin, "7");
        fields[1].value = -4.0;
        QSignalSpy spy(&panel, &PropertiesPanel::propertyEdited);
        panel.updateValues(fields);
        QVERIFY2(ySpin->text().startsWith("7"), qPrintable(ySpin->text()));
        QTest::keyClick(ySpin, Qt::Key_Enter);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(1).toDouble(), 7.0);

        // The same keys again (selection refreshed): still the same editors.
        panel.setObject("Particle ball", fields);
        QCOMPARE(panel.editor("position.x"), x);
    }

    // ---- SceneBrowser ------------------------------------------------------------------
    void browserListsIds() {
        SceneBrowser browser;
        browser.setScene(sampleScene());
        QCOMPARE(browser.ids(), QStringList({"ball", "p1", "b0", "ground", "s0", "flag"}));
        auto* tree = browser.findChild<QTreeWidget*>("objects");
        QCOMPARE(findItem(tree, "ball")->text(1), QString("m 1 kg, r 0.05 m"));
        QVERIFY(findItem(tree, "s0")->text(1).contains("k 1e6 N/m"));
        QVERIFY(findItem(tree, "flag")->text(1).contains("20 × 12 nodes"));
        QCOMPARE(tree->topLevelItem(0)->text(0), QString("Particles (2)"));

        browser.setFilter("grou");
        QVERIFY(!findItem(tree, "ground")->isHidden());
        QVERIFY(findItem(tree, "ball")->isHidden());
        QVERIFY(tree->topLevelItem(0)->isHidden());
        browser.setFilter(QString());
        QVERIFY(!findItem(tree, "ball")->isHidden());
    }

    void browserListsEveryKind() {
        // One object of every kind the scene format has: each gets its group and its row, so a
        // kind the browser forgot (disks and polygons were missing) shows here.
        SceneDesc scene = sampleScene();
        DiskDesc disk;
        disk.id = "wheel";
        disk.radius = 0.25;
        disk.mass = 2.0;
        scene.disks.push_back(disk);
        PolygonDesc triangle;
        triangle.id = "wedge";
        triangle.vertices = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        triangle.isStatic = true;
        scene.polygons.push_back(triangle);
        JointDesc hinge;
        hinge.id = "pin";
        hinge.a = "wheel";
        scene.joints.push_back(hinge);
        SceneBrowser browser;
        browser.setScene(scene);
        auto* tree = browser.findChild<QTreeWidget*>("objects");
        std::size_t kinds = 0;
        forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
            if (objectCount(scene, kind) == 0) return;
            ++kinds;
            for (std::size_t i = 0; i < objectCount(scene, kind); ++i) {
                const QString id = QString::fromStdString(objectId(scene, {kind, i}));
                QVERIFY2(findItem(tree, id), qPrintable(id));
            }
        });
        QCOMPARE(kinds, kObjectKindCount);
        QCOMPARE(tree->topLevelItemCount(), static_cast<int>(kObjectKindCount));
        QCOMPARE(findItem(tree, "wheel")->text(1), QString("r 0.25 m, m 2 kg"));
        QCOMPARE(findItem(tree, "wedge")->text(1), QString("3 vertices, static"));
    }

    void browserSelection() {
        SceneBrowser browser;
        browser.resize(300, 400);
        browser.setScene(sampleScene());
        browser.show();
        QVERIFY(QTest::qWaitForWindowExposed(&browser));
        QSignalSpy spy(&browser, &SceneBrowser::selectionChanged);
        auto* tree = browser.findChild<QTreeWidget*>("objects");

        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {},
                          tree->visualItemRect(findItem(tree, "ball")).center());
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.last().at(0).toStringList(), QStringList({"ball"}));
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, Qt::ControlModifier,
                          tree->visualItemRect(findItem(tree, "b0")).center());
        QCOMPARE(spy.last().at(0).toStringList(), QStringList({"ball", "b0"}));

        // From the canvas: no echo.
        const int before = spy.count();
        browser.setSelection({"ground", "s0"});
        QCOMPARE(spy.count(), before);
        QCOMPARE(browser.selection(), QStringList({"ground", "s0"}));
        browser.setScene(sampleScene());  // an edit elsewhere keeps the selection
        QCOMPARE(browser.selection(), QStringList({"ground", "s0"}));
        QCOMPARE(spy.count(), before);

        QSignalSpy deletes(&browser, &SceneBrowser::deleteRequested);
        tree->setFocus();
        QTest::keyClick(tree, Qt::Key_Delete);
        QCOMPARE(deletes.count(), 1);
    }

    // ---- pictures: each panel at dock width, to look at --------------------------------
    void renderPanels() {
        // Saves the picture and checks the panel fits a narrow dock.
        auto render = [](QWidget& panel, int height, const QString& name) {
            panel.resize(270, height > 0 ? height : panel.sizeHint().height());
            QVERIFY(panel.grab().save("/tmp/panel_" + name + ".png"));
            QVERIFY2(panel.minimumSizeHint().width() <= 270, qPrintable(name));
        };
        ParametersPanel parameters;
        QAction play("Play"), step("Step"), reset("Reset");
        parameters.setActions(&play, &step, &reset);
        parameters.setAdvice(
            "dt 0.0167 s is past symplectic Euler's stable limit 0.0021 s "
            "(ω_max 950 rad/s): expect a blow-up; try dt ≤ 0.002 or "
            "implicit Euler",
            true);
        render(parameters, 0, "parameters");
        EffectsPanel effects;
        effects.setEffects(sampleEffects());
        render(effects, 240, "effects");
        PropertiesPanel properties;
        properties.setObject("Particle ball", ballFields());
        properties.showError("mass must be > 0");
        render(properties, 260, "properties");
        PropertiesPanel empty;
        render(empty, 120, "properties_empty");
        SceneBrowser browser;
        browser.setScene(sampleScene());
        browser.setSelection({"b0"});
        render(browser, 300, "scene");
    }
};

QTEST_MAIN(TestPanels)
#include "tst_panels.moc"
