#include "ui/panels/SceneBrowser.h"

#include "physics/scene/ObjectKinds.h"
#include "physics/scene/SceneSchema.h"
#include "ui/panels/DisplayText.h"
#include "ui/panels/ShownNumber.h"

#include <QHash>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLineEdit>
#include <QScrollBar>
#include <QSet>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

#include <algorithm>
#include <string_view>
#include <variant>

namespace phasebox::ui {

namespace {
enum Column { kIdColumn = 0, kSummaryColumn = 1 };
constexpr int kIdRole = Qt::UserRole;         // object rows: the id
constexpr int kGroupRole = Qt::UserRole + 1;  // group rows: the scene array's key

// Three significant digits with the exponent as a person writes it: 0.05, 1e6, 2.5e-3.
QString num(double value) {
    QString text = shownNumber(value, 'g', 3);
    const qsizetype e = text.indexOf(QLatin1Char('e'));
    if (e < 0) return text;
    QString exponent = text.mid(e + 1);
    const bool negative = exponent.startsWith(QLatin1Char('-'));
    if (negative || exponent.startsWith(QLatin1Char('+'))) exponent.remove(0, 1);
    while (exponent.size() > 1 && exponent.startsWith(QLatin1Char('0'))) exponent.remove(0, 1);
    return text.left(e) + (negative ? QStringLiteral("e-") : QStringLiteral("e")) + exponent;
}

QString point(const Point2& p) {
    return QStringLiteral("(%1, %2)").arg(num(p[0]), num(p[1]));
}

QString qs(const std::string& text) {
    return QString::fromStdString(text);
}

QString qs(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}
}  // namespace

QString SceneBrowser::summary(const ParticleDesc& particle) {
    QString text = tr("m %1 kg, r %2 m").arg(num(particle.mass), num(particle.radius));
    if (particle.pinned) text += tr(", pinned");
    if (particle.charge != 0.0) text += tr(", q %1 C").arg(num(particle.charge));
    return text;
}

QString SceneBrowser::summary(const BoxDesc& box) {
    const QString size = tr("%1 × %2 m").arg(num(box.size[0]), num(box.size[1]));
    if (box.isStatic) return tr("%1, static").arg(size);
    return tr("%1, m %2 kg").arg(size, num(box.resolvedMass()));
}

QString SceneBrowser::summary(const DiskDesc& disk) {
    const QString radius = tr("r %1 m").arg(num(disk.radius));
    if (disk.isStatic) return tr("%1, static").arg(radius);
    return tr("%1, m %2 kg").arg(radius, num(disk.resolvedMass()));
}

QString SceneBrowser::summary(const PolygonDesc& polygon) {
    const QString shape = tr("%n vertices", nullptr, static_cast<int>(polygon.vertices.size()));
    if (polygon.isStatic) return tr("%1, static").arg(shape);
    return tr("%1, m %2 kg").arg(shape, num(polygon.resolvedMass()));
}

QString SceneBrowser::summary(const PlaneDesc& plane) {
    return tr("through %1, normal %2").arg(point(plane.point), point(plane.normal));
}

QString SceneBrowser::summary(const SpringDesc& spring) {
    const QString other = spring.b        ? qs(*spring.b)
                          : spring.anchor ? tr("anchor %1").arg(point(*spring.anchor))
                                          : tr("?");
    QString text = tr("%1 – %2, k %3 N/m").arg(qs(spring.a), other, num(spring.stiffness));
    if (spring.damping != 0.0) text += tr(", c %1 N·s/m").arg(num(spring.damping));
    return text;
}

QString SceneBrowser::summary(const JointDesc& joint) {
    const QString type = qs(schema::kJointTypeNames[static_cast<std::size_t>(joint.type)]);
    const QString other = joint.b ? qs(*joint.b) : tr("the world");
    QString text = joint.type == JointType::Track
                       ? tr("%1 of %2 on a %3")
                             .arg(type, qs(joint.a), joint.circle ? tr("circle") : tr("line"))
                       : tr("%1: %2 – %3").arg(type, qs(joint.a), other);
    if (joint.length) text += tr(", %1 m").arg(num(*joint.length));
    if (joint.motor) text += tr(", motor %1 rad/s").arg(num(joint.motor->speed));
    return text;
}

QString SceneBrowser::summary(const ClothDesc& cloth) {
    QString pinned;
    if (const auto* mode = std::get_if<std::string>(&cloth.pinned))
        pinned = qs(*mode);
    else
        pinned =
            tr("%n node(s)", nullptr,
               static_cast<int>(std::get<std::vector<std::array<int, 2>>>(cloth.pinned).size()));
    return tr("%1 × %2 nodes, %3 kg, pinned %4")
        .arg(cloth.resolution[0])
        .arg(cloth.resolution[1])
        .arg(num(cloth.mass), pinned);
}

QString SceneBrowser::groupTitle(const ParticleDesc&) {
    return tr("Particles");
}
QString SceneBrowser::groupTitle(const BoxDesc&) {
    return tr("Boxes");
}
QString SceneBrowser::groupTitle(const DiskDesc&) {
    return tr("Disks");
}
QString SceneBrowser::groupTitle(const PolygonDesc&) {
    return tr("Polygons");
}
QString SceneBrowser::groupTitle(const PlaneDesc&) {
    return tr("Planes");
}
QString SceneBrowser::groupTitle(const SpringDesc&) {
    return tr("Springs");
}
QString SceneBrowser::groupTitle(const ClothDesc&) {
    return tr("Cloths");
}
QString SceneBrowser::groupTitle(const JointDesc&) {
    return tr("Joints");
}

SceneBrowser::SceneBrowser(QWidget* parent) : QWidget(parent) {
    filter_ = new QLineEdit;
    filter_->setObjectName(QStringLiteral("filter"));
    filter_->setPlaceholderText(tr("Filter by id or summary"));
    filter_->setClearButtonEnabled(true);
    filter_->setAccessibleName(tr("Filter objects"));
    connect(filter_, &QLineEdit::textChanged, this, &SceneBrowser::applyFilter);

    tree_ = new QTreeWidget;
    tree_->setObjectName(QStringLiteral("objects"));
    tree_->setColumnCount(2);
    tree_->setHeaderLabels({tr("Id"), tr("Summary")});
    tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    tree_->setUniformRowHeights(true);
    tree_->setAllColumnsShowFocus(true);
    tree_->header()->setSectionResizeMode(kIdColumn, QHeaderView::Interactive);
    // Summaries whole, as wide as the longest: a narrow dock scrolls sideways rather than cut
    // them to "m 0,5 kg, r 0,…".
    tree_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    tree_->header()->setStretchLastSection(false);
    tree_->installEventFilter(this);
    connect(tree_, &QTreeWidget::itemSelectionChanged, this, &SceneBrowser::onTreeSelectionChanged);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(4);
    layout->addWidget(filter_);
    layout->addWidget(tree_, 1);
    setTabOrder(filter_, tree_);
    setMinimumWidth(220);
}

QTreeWidgetItem* SceneBrowser::addGroup(const QString& key, const QString& title, int count) {
    auto* group = new QTreeWidgetItem(tree_);
    group->setText(kIdColumn, QStringLiteral("%1 (%2)").arg(title).arg(count));
    group->setData(kIdColumn, kGroupRole, key);
    group->setFlags(Qt::ItemIsEnabled);  // a heading, not something to select
    QFont bold = tree_->font();
    bold.setBold(true);
    group->setFont(kIdColumn, bold);
    group->setFirstColumnSpanned(true);
    return group;
}

void SceneBrowser::addObject(QTreeWidgetItem* group, const QString& id, const QString& summary) {
    auto* item = new QTreeWidgetItem(group);
    // Shown cut (a long id would be laid out whole, and the column sized to it); the full id
    // stays in kIdRole, which selection uses.
    item->setText(kIdColumn, shownText(id));
    item->setText(kSummaryColumn, shownText(summary, 1000));
    item->setToolTip(kSummaryColumn, shownText(summary, 1000));
    item->setData(kIdColumn, kIdRole, id);
}

void SceneBrowser::setScene(const SceneDesc& scene) {
    const QStringList selected = selection();
    QHash<QString, bool> expanded;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* group = tree_->topLevelItem(i);
        expanded.insert(group->data(kIdColumn, kGroupRole).toString(), group->isExpanded());
    }
    const int scroll = tree_->verticalScrollBar() ? tree_->verticalScrollBar()->value() : 0;

    settingSelection_ = true;
    tree_->setUpdatesEnabled(false);
    tree_->clear();

    // A group per kind in the scene file's order, capped at kMaxRowsPerGroup rows.
    forEachKind([&]<typename D>(std::type_identity<D>, ObjectKind kind) {
        const std::vector<D>& objects = arrayOf<D>(scene);
        const std::size_t n = objects.size();
        if (n == 0) return;
        const QString key = qs(schema::table<D>().key);
        QTreeWidgetItem* group = addGroup(key, groupTitle(D{}), static_cast<int>(n));
        const std::size_t shown = std::min<std::size_t>(n, kMaxRowsPerGroup);
        for (std::size_t i = 0; i < shown; ++i)
            addObject(group, qs(objectId(scene, {kind, i})), summary(objects[i]));
        if (shown < n) {
            auto* more = new QTreeWidgetItem(group);
            more->setText(kIdColumn, tr("… and %1 more").arg(n - shown));
            more->setFirstColumnSpanned(true);
            more->setFlags(Qt::ItemIsEnabled);
        }
        group->setExpanded(expanded.value(key, true));
    });

    // The id column as wide as the longest id (group headings span both columns), so the
    // summaries get the rest of a narrow dock; capped so a long id cannot hide them.
    int idWidth = tree_->header()->fontMetrics().horizontalAdvance(tr("Id"));
    for (QTreeWidgetItemIterator it(tree_); *it; ++it)
        if (!(*it)->isFirstColumnSpanned())
            idWidth =
                std::max(idWidth, tree_->fontMetrics().horizontalAdvance((*it)->text(kIdColumn)));
    tree_->header()->resizeSection(
        kIdColumn, std::min(idWidth + 2 * tree_->indentation() + 12,
                            tree_->fontMetrics().horizontalAdvance(QLatin1Char('m')) * 18));

    const QSet<QString> keep(selected.cbegin(), selected.cend());
    for (QTreeWidgetItemIterator it(tree_); *it; ++it)
        if (keep.contains((*it)->data(kIdColumn, kIdRole).toString())) (*it)->setSelected(true);
    applyFilter();
    tree_->setUpdatesEnabled(true);
    if (tree_->verticalScrollBar()) tree_->verticalScrollBar()->setValue(scroll);
    settingSelection_ = false;
}

void SceneBrowser::setSelection(const QStringList& ids) {
    const QSet<QString> wanted(ids.cbegin(), ids.cend());
    settingSelection_ = true;
    tree_->clearSelection();
    QTreeWidgetItem* first = nullptr;
    for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
        if (!wanted.contains((*it)->data(kIdColumn, kIdRole).toString())) continue;
        (*it)->setSelected(true);
        if (!first) first = *it;
    }
    if (first) {
        tree_->setCurrentItem(first, kIdColumn, QItemSelectionModel::NoUpdate);
        tree_->scrollToItem(first);
    }
    settingSelection_ = false;
}

QStringList SceneBrowser::selection() const {
    QStringList ids;
    // Tree order rather than click order, so the same selection always reads the same.
    for (QTreeWidgetItemIterator it(tree_, QTreeWidgetItemIterator::Selected); *it; ++it) {
        const QString id = (*it)->data(kIdColumn, kIdRole).toString();
        if (!id.isEmpty()) ids << id;
    }
    return ids;
}

QStringList SceneBrowser::ids() const {
    QStringList out;
    for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
        const QString id = (*it)->data(kIdColumn, kIdRole).toString();
        if (!id.isEmpty()) out << id;
    }
    return out;
}

void SceneBrowser::setFilter(const QString& text) {
    filter_->setText(text);
}

void SceneBrowser::applyFilter() {
    const QString needle = filter_->text().trimmed();
    for (int g = 0; g < tree_->topLevelItemCount(); ++g) {
        QTreeWidgetItem* group = tree_->topLevelItem(g);
        int visible = 0;
        for (int i = 0; i < group->childCount(); ++i) {
            QTreeWidgetItem* item = group->child(i);
            const bool match = needle.isEmpty() ||
                               item->text(kIdColumn).contains(needle, Qt::CaseInsensitive) ||
                               item->text(kSummaryColumn).contains(needle, Qt::CaseInsensitive);
            item->setHidden(!match);
            visible += match ? 1 : 0;
        }
        group->setHidden(visible == 0 && !needle.isEmpty());
        // A match inside a collapsed group would otherwise stay invisible.
        if (!needle.isEmpty() && visible > 0) group->setExpanded(true);
    }
}

void SceneBrowser::onTreeSelectionChanged() {
    if (!settingSelection_) emit selectionChanged(selection());
}

bool SceneBrowser::eventFilter(QObject* watched, QEvent* event) {
    if (watched == tree_ &&
        (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        auto* key = static_cast<QKeyEvent*>(event);
        const bool isDelete = key->matches(QKeySequence::Delete) || key->key() == Qt::Key_Delete ||
                              key->key() == Qt::Key_Backspace;
        if (isDelete) {
            // Claim the key before a window-wide Delete action does, so the tree's own
            // selection is what gets deleted and the shortcut is never ambiguous.
            event->accept();
            if (event->type() == QEvent::KeyPress && !selection().isEmpty()) emit deleteRequested();
            return event->type() == QEvent::KeyPress;
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace phasebox::ui
