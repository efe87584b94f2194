#include "app/io/InputFile.h"

#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <utility>

#if defined(Q_OS_UNIX)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace phasebox::inputfile {

#if defined(Q_OS_UNIX)
namespace {
QString describeMode(mode_t mode) {
    if (S_ISREG(mode)) return {};
    if (S_ISDIR(mode)) return QStringLiteral("a folder");
    if (S_ISFIFO(mode)) return QStringLiteral("a FIFO (named pipe)");
    if (S_ISCHR(mode) || S_ISBLK(mode)) return QStringLiteral("a device");
    if (S_ISSOCK(mode)) return QStringLiteral("a socket");
    return QStringLiteral("not a regular file");
}
}  // namespace
#endif

QString irregularKind(const QString& path) {
    if (path.isEmpty() || path.startsWith(QLatin1Char(':'))) return {};
#if defined(Q_OS_UNIX)
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0) return {};
    return describeMode(st.st_mode);
#else
    const QFileInfo info(path);
    if (!info.exists() || info.isFile()) return {};
    return info.isDir() ? QStringLiteral("a folder") : QStringLiteral("not a regular file");
#endif
}

QString open(const QString& path, QFile& file, const QString& kind) {
    const QString cannot = QStringLiteral("cannot read the file: ");
    // The system's calls end a name at its first NUL: another file would be read.
    if (path.contains(QChar(u'\0')))
        return cannot + QStringLiteral("the name holds a NUL character");
#if defined(Q_OS_UNIX)
    if (!path.startsWith(QLatin1Char(':'))) {
        const int fd =
            ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) return cannot + QString::fromLocal8Bit(std::strerror(errno));
        struct stat st {};
        QString what;
        if (::fstat(fd, &st) != 0) {
            what = QString::fromLocal8Bit(std::strerror(errno));
        } else if (const QString irregular = describeMode(st.st_mode); !irregular.isEmpty()) {
            what = QStringLiteral("it is ") + irregular;
            if (!S_ISDIR(st.st_mode) && !irregular.startsWith(QLatin1String("not ")))
                what += QStringLiteral(", not a ") + kind;
        }
        if (!what.isEmpty()) {
            ::close(fd);
            return cannot + what;
        }
        // Back to blocking reads for the regular file; QFile owns the descriptor from here.
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
        if (!file.open(fd, QIODevice::ReadOnly, QFileDevice::AutoCloseHandle)) {
            ::close(fd);
            return cannot + file.errorString();
        }
        return {};
    }
#endif
    // QFile refuses a directory with "Unknown error", which tells the user nothing.
    const QFileInfo info(path);
    if (info.isDir()) return cannot + QStringLiteral("it is a folder");
    if (info.exists() && !info.isFile()) return cannot + QStringLiteral("it is not a regular file");
    file.setFileName(path);
    if (!file.open(QIODevice::ReadOnly)) return cannot + file.errorString();
    return {};
}

bool readAll(const QString& path, qint64 maxBytes, QByteArray* bytes, QString* error,
             const QString& kind) {
    auto fail = [&](const QString& what) {
        if (error) *error = path + QStringLiteral(": ") + what;
        return false;
    };
    QFile file;
    if (const QString refused = open(path, file, kind); !refused.isEmpty()) return fail(refused);
    const QString tooLarge = QStringLiteral("the file is larger than %1 bytes").arg(maxBytes);
    if (file.size() > maxBytes) return fail(tooLarge);
    // One byte past the limit rather than trusting size(), which is 0 for files under /proc.
    QByteArray read = file.read(maxBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return fail(QStringLiteral("cannot read the file: ") + file.errorString());
    if (read.size() > maxBytes) return fail(tooLarge);
    *bytes = std::move(read);
    return true;
}

}  // namespace phasebox::inputfile
