#pragma once
// Simulation > Worker Threads: every core (the default) or a fixed number of threads for the
// step's large loops. Applies at once to the document's world and to every world it builds
// after, and is stored for the next start. Only the timings change (World::setWorkers).

#include <QObject>

QT_BEGIN_NAMESPACE
class QActionGroup;
class QMenu;
class QSettings;
QT_END_NAMESPACE

namespace phasebox {

class Document;

class WorkerMenu : public QObject {
    Q_OBJECT

public:
    // Fills menu (object name "workerMenu"; its actions "workers_0" for every core, then
    // "workers_1", "workers_2", … up to the cores), every core checked.
    WorkerMenu(QMenu& menu, Document& document);
    // The stored choice, checked and applied to the document (with the window's other
    // settings, once the settings files are known to be safe to read: SettingsGuard).
    void readSettings(const QSettings& settings);

    // The stored choice (0: every core), and storing one.
    static int stored(const QSettings& settings);
    static void store(QSettings& settings, int workers);

signals:
    void message(const QString& text);

private:
    void choose(int workers);
    void offer(int workers);  // an action for the count, in order, unless there is one
    void check(int workers);

    Document& document_;
    QMenu* menu_ = nullptr;
    QActionGroup* group_ = nullptr;
};

}  // namespace phasebox
