#include "ui/panels/EffectsPanel.h"

#include "physics/core/EffectNames.h"
#include "physics/scene/SceneSchema.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/ShownNumber.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPixmap>
#include <QSignalBlocker>
#include <QStyle>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

namespace phasebox::ui {

namespace {
enum Column { kNameColumn = 0, kCostColumn = 1 };
constexpr int kNameRole = Qt::UserRole;

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// What each row does, for tooltips: the effects' force laws from the scene schema, and the
// stages the world runs by itself.
QString describe(const QString& name) {
    const QHash<QString, QString> descriptions = [] {
        QHash<QString, QString> out{
            {text(effectName::springs),
             EffectsPanel::tr("Spring forces; runs because the scene holds springs")},
            {QStringLiteral("contacts"),
             EffectsPanel::tr("Collision detection and contact impulses; runs because the scene "
                              "holds things that can touch")},
            {EffectsPanel::kIntegratorRow,
             EffectsPanel::tr("The integrator's own arithmetic: the step minus its effects and "
                              "contacts")},
        };
        schema::forEachEffect([&](const auto& table, auto) {
            if (!table.implied) out.insert(text(table.key), schemaText(table.description));
        });
        return out;
    }();
    return descriptions.value(name);
}
}  // namespace

const QStringList& EffectsPanel::contractEffects() {
    static const QStringList names = [] {
        QStringList out;
        // Effects the objects imply (Coulomb's law between charges) are not added by hand.
        schema::forEachEffect([&](const auto& table, auto) {
            if (!table.implied) out << text(table.key);
        });
        return out;
    }();
    return names;
}

QString EffectsPanel::displayName(const QString& name) {
    const QHash<QString, QString> names{
        {text(schema::key::gravity), tr("Gravity")},
        {text(schema::key::drag), tr("Drag")},
        {text(schema::key::newtonianGravity), tr("Newtonian gravity")},
        {text(schema::key::buoyancy), tr("Buoyancy")},
        {text(schema::key::wind), tr("Wind")},
        {text(schema::key::flocking), tr("Flocking")},
        {text(schema::key::particleCollisions), tr("Particle collisions")},
        {text(schema::key::coulomb), tr("Coulomb")},
        {text(effectName::springs), tr("Springs")},
        {QStringLiteral("contacts"), tr("Contacts")},
        {kIntegratorRow, tr("Integrator")},
        // The step's stages (StepProfile::kStageNames).
        {QStringLiteral("integrate"), tr("Integrate")},
        {QStringLiteral("collide"), tr("Collide")},
        {QStringLiteral("solve contacts"), tr("Solve contacts")},
        {QStringLiteral("solve joints"), tr("Solve joints")},
        {QStringLiteral("ledger"), tr("Ledger")},
        {QStringLiteral("guard"), tr("Guard")},
    };
    if (const auto found = names.find(name); found != names.end()) return *found;
    QString label = name;
    label.replace(QLatin1Char('_'), QLatin1Char(' '));
    if (!label.isEmpty()) label[0] = label[0].toUpper();
    return label;
}

QString EffectsPanel::formatMs(double ms) {
    if (!(ms >= 0.0) || !std::isfinite(ms)) return QStringLiteral("–");
    if (ms == 0.0) return QStringLiteral("0");
    // Three significant digits with their trailing zeros (1.20, not 1.2), so a column of
    // changing numbers keeps its shape; below 0.1 ms in microseconds, so that gravity's
    // 0.0000421 ms reads as 0.0421 µs and fits the column.
    const bool micro = ms < 0.1;
    const double value = micro ? ms * 1000.0 : ms;
    int decimals = std::max(0, 2 - static_cast<int>(std::floor(std::log10(value))));
    const double scale = std::pow(10.0, decimals);
    if (decimals > 0 && std::round(value * scale) >= 1000.0) --decimals;  // 9.996 → 10.0
    return shownNumber(value, 'f', std::min(decimals, 9)) +
           (micro ? QStringLiteral(" µs") : QStringLiteral(" ms"));
}

QString EffectsPanel::formatCost(double ms) {
    const QString time = formatMs(ms);
    if (!(ms >= 0.0) || !std::isfinite(ms)) return time;
    return ms == 0.0 ? tr("0 µs/step") : tr("%1/step").arg(time);
}

EffectsPanel::EffectsPanel(QWidget* parent) : QWidget(parent) {
    tree_ = new QTreeWidget;
    tree_->setObjectName(QStringLiteral("effects"));
    tree_->setColumnCount(2);
    tree_->setHeaderLabels({tr("Effect"), tr("CPU time")});
    tree_->headerItem()->setTextAlignment(kCostColumn, Qt::AlignRight | Qt::AlignVCenter);
    tree_->headerItem()->setToolTip(kCostColumn, tr("CPU time per step, over the last frames"));
    tree_->setRootIsDecorated(false);
    tree_->setUniformRowHeights(true);
    tree_->setAllColumnsShowFocus(true);
    tree_->setSelectionMode(QAbstractItemView::SingleSelection);
    QHeaderView* header = tree_->header();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(kNameColumn, QHeaderView::Stretch);
    // A fixed cost column: resizing to contents would relayout the view on every frame.
    header->setSectionResizeMode(kCostColumn, QHeaderView::Fixed);
    const int costWidth = std::max(tree_->fontMetrics().horizontalAdvance(formatCost(0.0000421)),
                                   header->fontMetrics().horizontalAdvance(tr("CPU time"))) +
                          16;
    header->resizeSection(kCostColumn, costWidth);
    connect(tree_, &QTreeWidget::itemChanged, this, &EffectsPanel::onItemChanged);
    const int indicator = style()->pixelMetric(QStyle::PM_IndicatorWidth, nullptr, tree_);
    tree_->setIconSize(QSize(indicator, indicator));
    QPixmap blank(indicator, indicator);
    blank.fill(Qt::transparent);
    blankIndicator_ = QIcon(blank);

    addMenu_ = new QMenu(this);
    addMenu_->setToolTipsVisible(true);
    addButton_ = new QToolButton;
    addButton_->setObjectName(QStringLiteral("addEffect"));
    addButton_->setText(tr("&Add effect"));
    addButton_->setToolTip(tr("Add an effect the scene does not simulate yet"));
    addButton_->setPopupMode(QToolButton::InstantPopup);
    addButton_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    addButton_->setFocusPolicy(Qt::StrongFocus);
    addButton_->setMenu(addMenu_);

    total_ = new QLabel;
    total_->setObjectName(QStringLiteral("total"));
    total_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    total_->setToolTip(tr("Time of one whole step: integrator, effects and contacts"));
    // Beside the Add button it wraps rather than run under it in a narrow dock.
    total_->setWordWrap(true);

    costNote_ = new QLabel;
    costNote_->setObjectName(QStringLiteral("costNote"));
    costNote_->setWordWrap(true);
    costNote_->hide();

    auto* bottom = new QHBoxLayout;
    bottom->addWidget(addButton_);
    bottom->addStretch(1);
    bottom->addWidget(total_);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(tree_, 1);
    layout->addWidget(createStageView());
    layout->addWidget(costNote_);
    layout->addLayout(bottom);
    setMinimumWidth(220);

    rebuildAddMenu();
    updateTotal(0.0);
}

void EffectsPanel::applyRow(QTreeWidgetItem* item, const EffectRow& row) {
    const QString description = row.tooltip.isEmpty() ? describe(row.name) : row.tooltip;
    const QString tip =
        description.isEmpty()
            ? row.name
            : QStringLiteral("%1 (%2)\n%3").arg(displayName(row.name), row.name, description);
    if (item->text(kNameColumn) != displayName(row.name))
        item->setText(kNameColumn, displayName(row.name));
    item->setData(kNameColumn, kNameRole, row.name);
    item->setToolTip(kNameColumn, tip);
    item->setToolTip(kCostColumn, tip);
    Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (row.toggleable) {
        flags |= Qt::ItemIsUserCheckable;
        item->setCheckState(kNameColumn, row.enabled ? Qt::Checked : Qt::Unchecked);
    } else {
        // An item with no check state data draws no box at all; a blank icon of the box's
        // width keeps its name in line with the switchable effects above it.
        item->setData(kNameColumn, Qt::CheckStateRole, QVariant());
        item->setIcon(kNameColumn, blankIndicator_);
    }
    item->setFlags(flags);
    // A stage the world runs by itself reads differently from an effect one can switch.
    QFont font = tree_->font();
    font.setItalic(!row.toggleable);
    item->setFont(kNameColumn, font);
    const QBrush text =
        palette().brush(row.enabled ? QPalette::Active : QPalette::Disabled, QPalette::Text);
    item->setForeground(kNameColumn, text);
    item->setForeground(kCostColumn, text);
    item->setTextAlignment(kCostColumn, Qt::AlignRight | Qt::AlignVCenter);
    const double ms = row.enabled ? row.msPerStep : -1.0;
    item->setText(kCostColumn, formatCost(ms));
    enabled_.insert(row.name, row.enabled);
    costs_.insert(row.name, ms);
}

void EffectsPanel::setEffects(const std::vector<EffectRow>& rows) {
    const QSignalBlocker blocker(tree_);  // updates are not user toggles
    QStringList names;
    for (const EffectRow& row : rows) names << row.name;

    if (names == effectNames()) {
        for (const EffectRow& row : rows) applyRow(items_.value(row.name), row);
    } else {
        QStringList selected;
        for (QTreeWidgetItem* item : tree_->selectedItems())
            selected << item->data(kNameColumn, kNameRole).toString();
        const QString current = tree_->currentItem()
                                    ? tree_->currentItem()->data(kNameColumn, kNameRole).toString()
                                    : QString();
        tree_->setUpdatesEnabled(false);
        tree_->clear();
        items_.clear();
        enabled_.clear();
        costs_.clear();
        for (const EffectRow& row : rows) {
            auto* item = new QTreeWidgetItem(tree_);
            applyRow(item, row);
            items_.insert(row.name, item);
            if (row.name == current)
                tree_->setCurrentItem(item, kNameColumn, QItemSelectionModel::NoUpdate);
            if (selected.contains(row.name)) item->setSelected(true);
        }
        tree_->setUpdatesEnabled(true);
        rebuildAddMenu();
    }
    double total = 0.0;
    for (double ms : costs_)
        if (ms > 0.0) total += ms;
    updateTotal(total);
}

void EffectsPanel::setCosts(std::span<const EffectCost> costs, long long steps,
                            double stepSeconds) {
    const double perStepMs = steps > 0 ? 1000.0 / static_cast<double>(steps) : 0.0;
    QHash<QString, double> measured;
    double sum = 0.0;
    for (const EffectCost& cost : costs) {
        const double ms = cost.seconds * perStepMs;
        measured.insert(QString::fromStdString(cost.name), ms);
        sum += ms;
    }
    const double total = stepSeconds > 0.0 ? stepSeconds * perStepMs : sum;
    measured.insert(kIntegratorRow, std::max(0.0, total - sum));

    const QSignalBlocker blocker(tree_);
    for (auto it = items_.cbegin(); it != items_.cend(); ++it) {
        const auto found = measured.constFind(it.key());
        // Before the first step nothing was measured: no figure rather than a zero.
        const double ms =
            steps > 0 && found != measured.cend() && enabled_.value(it.key()) ? *found : -1.0;
        costs_.insert(it.key(), ms);
        const QString text = formatCost(ms);
        // Setting equal text still repaints; most frames change only some digits.
        if (it.value()->text(kCostColumn) != text) it.value()->setText(kCostColumn, text);
    }
    updateTotal(steps > 0 ? total : -1.0);
}

void EffectsPanel::setCost(const QString& name, double msPerStep) {
    QTreeWidgetItem* item = items_.value(name);
    if (!item) return;
    const QSignalBlocker blocker(tree_);
    costs_.insert(name, msPerStep);
    item->setText(kCostColumn, formatCost(msPerStep));
    double total = 0.0;
    for (double ms : costs_)
        if (ms > 0.0) total += ms;
    updateTotal(total);
}

void EffectsPanel::updateTotal(double totalMs) {
    total_->setText(tr("total: %1 per step").arg(formatMs(totalMs)));
}

void EffectsPanel::onItemChanged(QTreeWidgetItem* item, int column) {
    if (column != kNameColumn || !(item->flags() & Qt::ItemIsUserCheckable)) return;
    const QString name = item->data(kNameColumn, kNameRole).toString();
    const bool enabled = item->checkState(kNameColumn) == Qt::Checked;
    if (enabled_.value(name) == enabled) return;  // a text or cost change, not a toggle
    enabled_.insert(name, enabled);
    {
        // Show the new state at once; the app confirms it with setEffects().
        const QSignalBlocker blocker(tree_);
        const QBrush text =
            palette().brush(enabled ? QPalette::Active : QPalette::Disabled, QPalette::Text);
        item->setForeground(kNameColumn, text);
        item->setForeground(kCostColumn, text);
    }
    emit effectToggled(name, enabled);
}

void EffectsPanel::rebuildAddMenu() {
    addMenu_->clear();
    for (const QString& name : addableEffects()) {
        QAction* action = addMenu_->addAction(displayName(name));
        action->setData(name);
        action->setToolTip(describe(name));
        connect(action, &QAction::triggered, this, [this, name] { emit addEffectRequested(name); });
    }
    addButton_->setEnabled(!addMenu_->isEmpty());
}

QStringList EffectsPanel::effectNames() const {
    QStringList names;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i)
        names << tree_->topLevelItem(i)->data(kNameColumn, kNameRole).toString();
    return names;
}

QStringList EffectsPanel::addableEffects() const {
    QStringList names;
    for (const QString& name : contractEffects())
        if (!items_.contains(name)) names << name;
    return names;
}

bool EffectsPanel::isEnabled(const QString& name) const {
    return enabled_.value(name);
}

QString EffectsPanel::costText(const QString& name) const {
    const QTreeWidgetItem* item = items_.value(name);
    return item ? item->text(kCostColumn) : QString();
}

QString EffectsPanel::totalText() const {
    return total_->text();
}

QTreeWidget* EffectsPanel::createStageView() {
    stages_ = new QTreeWidget;
    stages_->setObjectName(QStringLiteral("stages"));
    stages_->setHeaderLabels({tr("Stage of the step"), tr("per step")});
    stages_->headerItem()->setTextAlignment(kCostColumn, Qt::AlignRight | Qt::AlignVCenter);
    stages_->setToolTip(tr("Where a step's time goes, stage by stage, in the order they run"));
    stages_->setRootIsDecorated(false);
    stages_->setSelectionMode(QAbstractItemView::NoSelection);
    stages_->setFocusPolicy(Qt::NoFocus);
    stages_->header()->setStretchLastSection(false);
    stages_->header()->setSectionResizeMode(kNameColumn, QHeaderView::Stretch);
    stages_->header()->setSectionResizeMode(kCostColumn, QHeaderView::Fixed);
    // Its costs have no "per step" of their own (the header says it): a narrower column leaves
    // the stages' names whole ("Detectar colisiones").
    stages_->header()->resizeSection(
        kCostColumn, std::max(stages_->fontMetrics().horizontalAdvance(formatMs(0.0000421)),
                              stages_->header()->fontMetrics().horizontalAdvance(tr("per step"))) +
                         16);
    stages_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    stages_->hide();  // until the first profile
    return stages_;
}

void EffectsPanel::setStageCosts(const std::vector<StageCost>& stages) {
    while (stages_->topLevelItemCount() > static_cast<int>(stages.size()))
        delete stages_->takeTopLevelItem(stages_->topLevelItemCount() - 1);
    for (std::size_t i = 0; i < stages.size(); ++i) {
        QTreeWidgetItem* item = stages_->topLevelItem(static_cast<int>(i));
        if (!item) {
            item = new QTreeWidgetItem(stages_);
            item->setTextAlignment(kCostColumn, Qt::AlignRight | Qt::AlignVCenter);
        }
        item->setText(kNameColumn, displayName(stages[i].name));
        item->setData(kNameColumn, Qt::UserRole, stages[i].name);
        item->setText(kCostColumn, formatMs(stages[i].msPerStep));
    }
    // Tall enough for every row: the list is short and should never scroll.
    const int rows = stages_->topLevelItemCount();
    const int rowHeight = rows > 0 ? stages_->sizeHintForRow(0) : 0;
    stages_->setFixedHeight(stages_->header()->sizeHint().height() + rows * rowHeight +
                            2 * stages_->frameWidth());
    stages_->setVisible(rows > 0);
}

QString EffectsPanel::stageCostText(const QString& stage) const {
    for (int i = 0; i < stages_->topLevelItemCount(); ++i)
        if (stages_->topLevelItem(i)->data(kNameColumn, Qt::UserRole).toString() == stage)
            return stages_->topLevelItem(i)->text(kCostColumn);
    return {};
}

void EffectsPanel::setCostNote(const QString& note) {
    costNote_->setText(note);
    costNote_->setVisible(!note.isEmpty());
}

QString EffectsPanel::costNote() const {
    return costNote_->text();
}

}  // namespace phasebox::ui
