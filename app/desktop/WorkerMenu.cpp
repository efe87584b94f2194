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
    const int cores = WorkerPool::allCores();
    const int chosen = stored(QSettings());
    auto* group = new QActionGroup(&menu);
    // Every core, then one thread, then powers of two up to the cores (and the stored choice,
    // should it be more than this machine has).
    QList<int> counts{0, 1};
    for (int n = 2; n <= std::max(cores, chosen); n *= 2) counts << n;
    if (cores > 1 && !counts.contains(cores)) counts << cores;
    if (chosen > 0 && !counts.contains(chosen)) counts << chosen;
    std::sort(counts.begin() + 1, counts.end());
    for (const int n : std::as_const(counts)) {
        QAction* a = menu.addAction(n == 0 ? tr("&Every Core (%n threads)", nullptr, cores)
                                           : tr("%n Thread(s)", nullptr, n));
        a->setCheckable(true);
        a->setChecked(n == chosen);
        a->setObjectName(QStringLiteral("workers_%1").arg(n));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, n] { choose(n); });
    }
    document_.setWorkers(chosen);
}

void WorkerMenu::choose(int workers) {
    QSettings settings;
    store(settings, workers);
    document_.setWorkers(workers);
    emit message(workers == 0 ? tr("The step shares its work among every core.")
                              : tr("The step runs on %n thread(s).", nullptr, workers));
}

}  // namespace phasebox
