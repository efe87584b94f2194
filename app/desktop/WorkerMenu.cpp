#include "app/desktop/WorkerMenu.h"

#include "app/document/Document.h"
#include "physics/core/WorkerPool.h"

#include <QActionGroup>
#include <QMenu>
#include <QSettings>

#include <algorithm>

namespace phasebox {

namespace {
const QString kKey = QStringLiteral("simulation/workers");
constexpr int kMostOffered = 64;
}  // namespace

int WorkerMenu::stored(const QSettings& settings) {
    bool ok = false;
    const int n = settings.value(kKey, 0).toInt(&ok);
    return ok ? std::clamp(n, 0, kMostOffered) : 0;
}

void WorkerMenu::store(QSettings& settings, int workers) {
    settings.setValue(kKey, workers);
}

WorkerMenu::WorkerMenu(QMenu& menu, Document& document) : QObject(&menu), document_(document) {
    menu.setObjectName(QStringLiteral("workerMenu"));
    menu_ = &menu;
    group_ = new QActionGroup(&menu);
    offer(0);
    offer(1);
    const int cores = WorkerPool::allCores();
    for (int n = 2; n <= cores; n *= 2) offer(n);
    offer(cores);
    check(0);
}

void WorkerMenu::offer(int workers) {
    // Every core first, then the counts in order, each once.
    QList<QAction*> actions = menu_->actions();
    int at = 0;
    for (; at < actions.size(); ++at) {
        const int n = actions[at]->data().toInt();
        if (n == workers) return;
        if (workers > 0 && n > workers) break;
    }
    const int cores = WorkerPool::allCores();
    auto* a = new QAction(workers == 0 ? tr("&Every Core (%n threads)", nullptr, cores)
                                       : tr("%n Thread(s)", nullptr, workers),
                          menu_);
    a->setCheckable(true);
    a->setData(workers);
    a->setObjectName(QStringLiteral("workers_%1").arg(workers));
    group_->addAction(a);
    menu_->insertAction(at < actions.size() ? actions[at] : nullptr, a);
    connect(a, &QAction::triggered, this, [this, workers] { choose(workers); });
}

void WorkerMenu::check(int workers) {
    for (QAction* a : menu_->actions()) a->setChecked(a->data().toInt() == workers);
}

void WorkerMenu::readSettings(const QSettings& settings) {
    const int workers = stored(settings);
    offer(workers);  // a count stored on a machine with more cores
    check(workers);
    document_.setWorkers(workers);
}

void WorkerMenu::choose(int workers) {
    QSettings settings;
    store(settings, workers);
    document_.setWorkers(workers);
    emit message(workers == 0 ? tr("The step shares its work among every core.")
                              : tr("The step runs on %n thread(s).", nullptr, workers));
}

}  // namespace phasebox
