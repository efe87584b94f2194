#include "app/desktop/SceneLibraryMenu.h"

#include "app/io/SceneIO.h"
#include "ui/panels/BuiltinText.h"
#include "ui/panels/DisplayText.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace phasebox {

QStringList builtInScenes(const QString& folder) {
    QStringList paths;
    const QDir dir(folder);
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        paths.append(dir.filePath(name));
    return paths;
}

void fillSceneLibraryMenu(QMenu& menu, const QString& folder,
                          const std::function<void(const QString&)>& open) {
    for (const QString& path : builtInScenes(folder)) {
        const SceneLoadResult loaded = SceneIO::load(path);
        const QString title = loaded.ok() && !loaded.scene->name.empty()
                                  ? ui::shownText(ui::sceneText(loaded.scene->name))
                                  : QFileInfo(path).completeBaseName();
        QAction* a = menu.addAction(title, &menu, [open, path] { open(path); });
        if (loaded.ok())
            a->setToolTip(ui::shownDescription(ui::sceneText(loaded.scene->description)));
        a->setData(path);
    }
    menu.setToolTipsVisible(true);
    menu.setEnabled(!menu.isEmpty());
}

RecentFiles::RecentFiles(QMenu& menu, std::function<void(const QString&)> open, QObject* parent)
    : QObject(parent), menu_(menu), open_(std::move(open)) {
    updateMenu();
}

void RecentFiles::add(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    paths_.removeAll(absolute);
    paths_.prepend(absolute);
    while (paths_.size() > kMaxFiles) paths_.removeLast();
    updateMenu();
}

void RecentFiles::readSettings(const QSettings& settings) {
    // Only names are read (no file is opened until one is chosen); a damaged or hand-edited
    // list is cut to kMaxFiles names that a system could hold (empty, over 4096 characters
    // or holding a NUL are dropped).
    paths_.clear();
    const QStringList stored = settings.value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : stored) {
        if (paths_.size() >= kMaxFiles) break;
        if (!path.isEmpty() && path.size() <= 4096 && !path.contains(QChar(u'\0')) &&
            !paths_.contains(path))
            paths_.append(path);
    }
    updateMenu();
}

void RecentFiles::writeSettings(QSettings& settings) const {
    settings.setValue(QStringLiteral("recentFiles"), paths_);
}

void RecentFiles::updateMenu() {
    menu_.clear();
    for (const QString& path : paths_)
        menu_
            .addAction(ui::shownText(QFileInfo(path).fileName()), this,
                       [this, path] { open_(path); })
            ->setToolTip(ui::shownText(path, 1000));
    menu_.setEnabled(!paths_.isEmpty());
}

}  // namespace phasebox
