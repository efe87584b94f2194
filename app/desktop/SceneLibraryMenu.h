#pragma once
// The built-in scenes (File → Examples, File → Lessons) and the recently opened files
// (File → Open Recent): the two menus of scenes the main window offers besides Open.

#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>

QT_BEGIN_NAMESPACE
class QMenu;
class QSettings;
QT_END_NAMESPACE

namespace phasebox {

// The built-in scenes of a resource folder (":/scenes" for the examples, ":/lessons"), by
// file name.
QStringList builtInScenes(const QString& folder);

// Fills menu with the scenes of a resource folder, titled by their names, their descriptions
// as tooltips and their paths as the actions' data; open is called with the chosen path.
void fillSceneLibraryMenu(QMenu& menu, const QString& folder,
                          const std::function<void(const QString&)>& open);

// File → Open Recent: the last kMaxFiles files opened or saved, newest first.
class RecentFiles : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaxFiles = 8;

    RecentFiles(QMenu& menu, std::function<void(const QString&)> open, QObject* parent = nullptr);
    void add(const QString& path);
    QStringList paths() const { return paths_; }
    void readSettings(const QSettings& settings);
    void writeSettings(QSettings& settings) const;

private:
    void updateMenu();

    QMenu& menu_;
    std::function<void(const QString&)> open_;
    QStringList paths_;
};

}  // namespace phasebox
