#pragma once
// The effects panel: what the scene simulates and what each part costs per step. Only the
// effects a scene lists run (an absent one costs nothing), so the list is also the menu of
// what could be added. Toggles and additions are reported as signals; the app edits the scene.

#include "physics/world/World.h"  // EffectCost

#include <QHash>
#include <QIcon>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <span>
#include <vector>

QT_BEGIN_NAMESPACE
class QLabel;
class QMenu;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;
QT_END_NAMESPACE

namespace phasebox::ui {

struct EffectRow {
    // The scene-format key of an effect (gravity, newtonian_gravity, …) or a world stage
    // (springs, contacts, integrator), as World::effectCosts() and --json name them.
    QString name;
    bool enabled = true;
    // false: a stage the world runs because of what the scene holds (springs, contacts) or
    // the integrator itself; shown without a check box.
    bool toggleable = true;
    double msPerStep = 0.0;  // negative or NaN: not running, shown as "–"
    QString tooltip;
};

// One stage of the world's step (World::stepProfile(): integrate, collide, solve contacts, …)
// and its mean cost.
struct StageCost {
    QString name;
    double msPerStep = 0.0;  // negative or NaN: the stage has not run, shown as "–"
};

class EffectsPanel : public QWidget {
    Q_OBJECT
public:
    // The row name whose cost setCosts() fills with the rest of the step: the integrator's
    // own arithmetic once effects and contacts are taken out.
    static inline const QString kIntegratorRow = QStringLiteral("integrator");

    explicit EffectsPanel(QWidget* parent = nullptr);

    // The rows, in order. Rows are updated in place when the names are unchanged, and the
    // selection (by name) survives a change of rows. Does not emit effectToggled.
    void setEffects(const std::vector<EffectRow>& rows);

    // The cost column from the world's profile, cheap enough for every frame: `costs` are
    // seconds accumulated over `steps` steps (World::effectCosts()), `stepSeconds` the whole
    // stepping time over the same steps (World::integratorSeconds()), which gives the total
    // and the integrator row. Rows missing from `costs` are not running and show "–".
    void setCosts(std::span<const EffectCost> costs, long long steps, double stepSeconds);
    // One row's cost in ms per step; the total becomes the sum of the rows.
    void setCost(const QString& name, double msPerStep);

    // The step profile under the effects: each stage of the world's step in the order it runs,
    // the coarse view of which the effect rows are the finer one. Rows are updated in place.
    void setStageCosts(const std::vector<StageCost>& stages);
    QString stageCostText(const QString& stage) const;  // empty for an unknown stage
    // A line under the costs saying what they are of (empty: none, the live run's costs).
    void setCostNote(const QString& note);
    QString costNote() const;
    QStringList effectNames() const;     // the rows' names, in order
    QStringList addableEffects() const;  // CONTRACT §1 effects not in the rows
    bool isEnabled(const QString& name) const;
    QString costText(const QString& name) const;
    QString totalText() const;
    QMenu* addMenu() const { return addMenu_; }

    // The effects of CONTRACT.md §1, in its order.
    static const QStringList& contractEffects();
    // The row name for people: newtonian_gravity → "Newtonian gravity".
    static QString displayName(const QString& name);
    // "1.23", "0.0123", "123": three significant digits, "–" when not running.
    static QString formatMs(double ms);
    // A cost cell: formatMs with its unit per step ("2.00 µs/step"), "–" when not running.
    static QString formatCost(double ms);

signals:
    void effectToggled(const QString& name, bool enabled);
    void addEffectRequested(const QString& name);

private:
    void applyRow(QTreeWidgetItem* item, const EffectRow& row);
    void rebuildAddMenu();
    void updateTotal(double totalMs);
    void onItemChanged(QTreeWidgetItem* item, int column);

    QTreeWidget* createStageView();

    QTreeWidget* tree_ = nullptr;
    QTreeWidget* stages_ = nullptr;  // the step profile, one row per stage
    QToolButton* addButton_ = nullptr;
    QMenu* addMenu_ = nullptr;
    QLabel* total_ = nullptr;
    QLabel* costNote_ = nullptr;
    QIcon blankIndicator_;
    QHash<QString, QTreeWidgetItem*> items_;
    QHash<QString, bool> enabled_;  // the last state shown, to tell user toggles from updates
    QHash<QString, double> costs_;  // ms per step by row, for the total of setCost()
};

}  // namespace phasebox::ui
