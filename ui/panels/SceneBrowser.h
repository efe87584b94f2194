#pragma once
// The scene browser: the scene's objects grouped by kind, with ids and a short summary. It
// reports the user's selection and Delete key; the canvas and the app keep it in step with
// setSelection(), which does not echo back.

#include "physics/scene/SceneDesc.h"

#include <QString>
#include <QStringList>
#include <QWidget>

QT_BEGIN_NAMESPACE
class QLineEdit;
class QTreeWidget;
class QTreeWidgetItem;
QT_END_NAMESPACE

namespace phasebox::ui {

class SceneBrowser : public QWidget {
    Q_OBJECT
public:
    // Past this many objects of one kind the rest are summarised in one row: a tree of a
    // hundred thousand items takes seconds to build, and no one scrolls through it.
    static constexpr int kMaxRowsPerGroup = 5000;

    explicit SceneBrowser(QWidget* parent = nullptr);

    // Rebuilds the tree; the selection, the expanded groups and the filter survive.
    void setScene(const SceneDesc& scene);
    // Selects these ids (others deselected) without emitting selectionChanged.
    void setSelection(const QStringList& ids);
    QStringList selection() const;
    // Every listed id, in tree order (cloths by their id, not their nodes).
    QStringList ids() const;
    void setFilter(const QString& text);

    // "m 1 kg, r 0.05 m" and the like, as shown in the tree: one per kind (setScene visits
    // every kind of physics/scene/ObjectKinds.h, so a kind without one does not compile).
    static QString summary(const ParticleDesc& particle);
    static QString summary(const BoxDesc& box);
    static QString summary(const DiskDesc& disk);
    static QString summary(const PolygonDesc& polygon);
    static QString summary(const PlaneDesc& plane);
    static QString summary(const SpringDesc& spring);
    static QString summary(const ClothDesc& cloth);
    static QString summary(const JointDesc& joint);
    // The heading of a kind's group ("Particles"), likewise one per kind.
    static QString groupTitle(const ParticleDesc&);
    static QString groupTitle(const BoxDesc&);
    static QString groupTitle(const DiskDesc&);
    static QString groupTitle(const PolygonDesc&);
    static QString groupTitle(const PlaneDesc&);
    static QString groupTitle(const SpringDesc&);
    static QString groupTitle(const ClothDesc&);
    static QString groupTitle(const JointDesc&);

signals:
    void selectionChanged(const QStringList& ids);
    void deleteRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QTreeWidgetItem* addGroup(const QString& key, const QString& title, int count);
    void addObject(QTreeWidgetItem* group, const QString& id, const QString& summary);
    void applyFilter();
    void onTreeSelectionChanged();

    QLineEdit* filter_ = nullptr;
    QTreeWidget* tree_ = nullptr;
    bool settingSelection_ = false;
};

}  // namespace phasebox::ui
