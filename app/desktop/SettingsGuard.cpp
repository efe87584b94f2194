#include "app/desktop/SettingsGuard.h"

#include "app/io/InputFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace phasebox {

bool guardSettingsFiles(QStringList* problems, bool repair) {
    bool safe = true;
    if (QSettings::defaultFormat() != QSettings::NativeFormat &&
        QSettings::defaultFormat() != QSettings::IniFormat)
        return safe;
#if defined(Q_OS_UNIX) && !defined(Q_OS_DARWIN)
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation);
    const QString organization = QCoreApplication::organizationName().isEmpty()
                                     ? QStringLiteral("Unknown Organization")  // as QSettings
                                     : QCoreApplication::organizationName();
    const QString application = QCoreApplication::applicationName();
    QStringList paths{folder + QLatin1Char('/') + organization + QStringLiteral(".conf")};
    if (!application.isEmpty())
        paths.prepend(folder + QLatin1Char('/') + organization + QLatin1Char('/') + application +
                      QStringLiteral(".conf"));
    constexpr qint64 kMaxSettingsBytes = 1024 * 1024;
    for (const QString& path : std::as_const(paths)) {
        if (!repair) {
            const QFileInfo info(path);
            if (!inputfile::irregularKind(path).isEmpty() ||
                (info.isFile() && info.size() > kMaxSettingsBytes))
                return false;
            continue;
        }
        if (const QString kind = inputfile::irregularKind(path); !kind.isEmpty()) {
            const bool removed = QFileInfo(path).isDir() ? QDir().rmdir(path) : QFile::remove(path);
            safe = safe && removed;
            *problems << QStringLiteral(
                             "%1: it is %2, not a settings file; %3 (default settings used)")
                             .arg(path, kind,
                                  removed ? QStringLiteral("removed") : QStringLiteral("ignored"));
        } else if (const QFileInfo info(path); info.isFile() && info.size() > kMaxSettingsBytes) {
            const QString aside = path + QStringLiteral(".too-large");
            QFile::remove(aside);
            const bool moved = QFile::rename(path, aside);
            safe = safe && moved;
            *problems << QStringLiteral(
                             "%1: the settings file is larger than 1 MiB; %2 (default "
                             "settings used)")
                             .arg(path, moved ? QStringLiteral("moved to ") + aside
                                              : QStringLiteral("could not move it aside"));
        }
    }
#endif
    return safe;
}

}  // namespace phasebox
