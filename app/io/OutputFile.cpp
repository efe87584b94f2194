#include "app/io/OutputFile.h"

#include <QFile>
#include <QFileInfo>
#include <QIODevice>
#include <QSaveFile>

#include <csignal>
#include <mutex>

#if defined(Q_OS_UNIX)
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#else
#include <cstdio>
#define STDOUT_FILENO 1
#endif

namespace phasebox {

namespace {

// What OutputFile hands out to write to: every write goes through OutputFile::write, which
// checks it. QSaveFile alone commits a file cut short: a write past a file-size limit or onto
// a full disk returns fewer bytes with no error set, and commit() then succeeds on the
// truncated copy (and QTextStream, which notices, cannot tell QSaveFile).
class CheckedDevice : public QIODevice {
public:
    explicit CheckedDevice(OutputFile& owner) : owner_(owner) {
        QIODevice::open(QIODevice::WriteOnly | QIODevice::Unbuffered);
    }
    bool isSequential() const override { return true; }

protected:
    qint64 readData(char*, qint64) override { return -1; }
    qint64 writeData(const char* data, qint64 size) override {
        return owner_.write(QByteArray::fromRawData(data, static_cast<qsizetype>(size))) ? size
                                                                                         : -1;
    }

private:
    OutputFile& owner_;
};

// Past RLIMIT_FSIZE the kernel sends SIGXFSZ, whose default action ends the process without a
// word; ignored, the write fails with EFBIG ("File too large"), which is reported like a full
// disk. Only a default disposition is changed: a program's own handler stays.
void ignoreFileSizeSignal() {
#if defined(Q_OS_UNIX)
    static std::once_flag once;
    std::call_once(once, [] {
        struct sigaction current {};
        if (::sigaction(SIGXFSZ, nullptr, &current) == 0 && current.sa_handler == SIG_DFL)
            std::signal(SIGXFSZ, SIG_IGN);
    });
#endif
}

std::atomic<const std::atomic<bool>*> gInterruptFlag{nullptr};

bool interruptRequested() {
    const std::atomic<bool>* flag = gInterruptFlag.load();
    return flag && flag->load(std::memory_order_relaxed);
}

enum class Kind { Missing, Regular, Folder, Special };

// What is at path now (following symbolic links). Anything under /dev or /proc counts as
// special whatever it points to: /dev/stdout may lead to a regular file that the shell opened,
// and putting a new file in its place would cut the shell's own output off.
Kind kindOf(const QString& path) {
#if defined(Q_OS_UNIX)
    const QString absolute = QFileInfo(path).absoluteFilePath();
    if (absolute.startsWith(QLatin1String("/dev/")) || absolute.startsWith(QLatin1String("/proc/")))
        return Kind::Special;
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0) return Kind::Missing;
    if (S_ISDIR(st.st_mode)) return Kind::Folder;
    return S_ISREG(st.st_mode) ? Kind::Regular : Kind::Special;
#else
    const QFileInfo info(path);
    if (!info.exists()) return Kind::Missing;
    if (info.isDir()) return Kind::Folder;
    return info.isFile() ? Kind::Regular : Kind::Special;
#endif
}

}  // namespace

bool OutputFile::isStandardOutput(const QString& path) {
    if (path == QLatin1String("-") || path == QLatin1String("/dev/stdout")) return true;
#if defined(Q_OS_UNIX)
    if (path.isEmpty() || path.contains(QChar(u'\0'))) return false;
    struct stat named {
    }, out{};
    if (::stat(QFile::encodeName(path).constData(), &named) != 0 ||
        ::fstat(STDOUT_FILENO, &out) != 0)
        return false;
    // Devices are left alone: /dev/null or a terminal written twice loses nothing.
    if (S_ISCHR(out.st_mode) || S_ISBLK(out.st_mode)) return false;
    return named.st_dev == out.st_dev && named.st_ino == out.st_ino;
#else
    return false;
#endif
}

QString OutputFile::unusablePath(const QString& path) {
#if defined(Q_OS_UNIX)
    if (path.isEmpty() || path.contains(QChar(u'\0'))) return {};
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0 && errno == ELOOP)
        return QStringLiteral(
            "it is a loop of symbolic links (too many levels); it would be replaced by a "
            "regular file");
#else
    (void)path;
#endif
    return {};
}

void OutputFile::setInterruptFlag(const std::atomic<bool>* flag) {
    gInterruptFlag.store(flag);
}

OutputFile::OutputFile(QString path, QString what)
    : path_(std::move(path)), what_(std::move(what)) {}

OutputFile::~OutputFile() {
    if (open_) cancel();
}

bool OutputFile::sameFile(const QString& a, const QString& b) {
    if (isStandardOutput(a) || isStandardOutput(b)) return false;
    if (a.contains(QChar(u'\0')) || b.contains(QChar(u'\0'))) return false;
#if defined(Q_OS_UNIX)
    struct stat sa {
    }, sb{};
    if (::stat(QFile::encodeName(a).constData(), &sa) != 0 ||
        ::stat(QFile::encodeName(b).constData(), &sb) != 0)
        return false;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
#else
    const QString ca = QFileInfo(a).canonicalFilePath(), cb = QFileInfo(b).canonicalFilePath();
    return !ca.isEmpty() && ca == cb;
#endif
}

bool OutputFile::writeAll(const QString& path, const QByteArray& bytes, QString* error,
                          const QString& what) {
    OutputFile file(path, what);
    const bool ok = file.open() && file.write(bytes) && file.commit();
    if (!ok && error) *error = file.error();
    return ok;
}

bool OutputFile::open() {
    error_.clear();
    ignoreFileSizeSignal();
    // The system's calls end a name at its first NUL, so the file written would be another
    // one than the name says (found by fuzz_cli_outputs).
    if (path_.contains(QChar(u'\0'))) return fail(QStringLiteral("the name holds a NUL character"));
    if (const QString why = unusablePath(path_); !why.isEmpty()) return fail(why);
    if (isStandardOutput(path_)) {
        inPlace_ = true;
        direct_ = std::make_unique<QFile>();
        if (!direct_->open(STDOUT_FILENO, QIODevice::WriteOnly | QIODevice::Unbuffered,
                           QFileDevice::DontCloseHandle))
            return fail(direct_->errorString());
    } else {
        switch (kindOf(path_)) {
            case Kind::Folder:
                return fail(QStringLiteral("it is a folder"));
            case Kind::Special:
                // A device, FIFO or socket: written where it is (a FIFO waits for its reader).
                inPlace_ = true;
                direct_ = std::make_unique<QFile>(path_);
                if (!direct_->open(QIODevice::WriteOnly | QIODevice::Unbuffered))
                    return fail(direct_->errorString());
                break;
            case Kind::Missing:
            case Kind::Regular:
                inPlace_ = false;
                saveFile_ = std::make_unique<QSaveFile>(path_);
                // No direct-write fallback: writing over the old file in place is what a
                // failure must never cost.
                saveFile_->setDirectWriteFallback(false);
                if (!saveFile_->open(QIODevice::WriteOnly | QIODevice::Unbuffered))
                    return fail(saveFile_->errorString());
                break;
        }
    }
    open_ = true;
    checked_ = std::make_unique<CheckedDevice>(*this);
    return true;
}

QIODevice* OutputFile::device() const {
    return checked_.get();
}

QIODevice* OutputFile::target() const {
    if (saveFile_) return saveFile_.get();
    return direct_.get();
}

bool OutputFile::write(const QByteArray& bytes) {
    if (failed()) return false;
    if (!open_) return fail(QStringLiteral("the file is not open"));
    if (direct_) return writeDirect(bytes.constData(), bytes.size());
    QIODevice* device = target();
    qint64 done = 0;
    const qint64 size = bytes.size();
    // A short write is retried: the next attempt reports why it stopped (EFBIG, ENOSPC).
    while (done < size) {
        const qint64 n = device->write(bytes.constData() + done, size - done);
        if (n <= 0) return fail(reason(done, size));
        done += n;
    }
    return true;
}

bool OutputFile::writeDirect(const char* data, qint64 size) {
#if defined(Q_OS_UNIX)
    const int fd = direct_->handle();
    qint64 done = 0;
    while (done < size) {
        if (interruptRequested()) {
            // Interrupted already: the results so far may still go out, but a reader that
            // takes nothing for a second does not keep the program waiting (`| sleep 1000`).
            pollfd p{fd, POLLOUT, 0};
            if (::poll(&p, 1, 1000) == 0) {
                interrupted_ = true;
                return fail(QStringLiteral("interrupted while the output was blocked"));
            }
        }
        const ssize_t n = ::write(fd, data + done, static_cast<size_t>(size - done));
        if (n < 0 && errno == EINTR) {
            if (!interruptRequested()) continue;
            interrupted_ = true;
            return fail(QStringLiteral("interrupted while the output was blocked"));
        }
        if (n < 0) return fail(QString::fromLocal8Bit(std::strerror(errno)));
        if (n == 0) return fail(reason(done, size));
        done += n;
    }
    return true;
#else
    qint64 done = 0;
    while (done < size) {
        const qint64 n = direct_->write(data + done, size - done);
        if (n <= 0) return fail(reason(done, size));
        done += n;
    }
    return true;
#endif
}

bool OutputFile::commit() {
    if (!open_) {
        if (!failed()) fail(QStringLiteral("the file is not open"));
        return false;
    }
    if (failed()) {
        cancel();
        return false;
    }
    open_ = false;
    if (saveFile_) {
        // Until commit() the old file is untouched; commit renames the finished copy over it.
        if (!saveFile_->commit()) return fail(saveFile_->errorString());
        return true;
    }
    if (!direct_->flush()) return fail(reason());
    direct_->close();
    if (direct_->error() != QFileDevice::NoError) return fail(reason());
    return true;
}

void OutputFile::cancel() {
    open_ = false;
    if (saveFile_) {
        saveFile_->cancelWriting();
        saveFile_->commit();  // with writing cancelled, this only removes the temporary copy
    }
    if (direct_) direct_->close();
}

bool OutputFile::fail(const QString& why) {
    if (error_.isEmpty()) {
        error_ = isStandardOutput(path_)
                     ? QStringLiteral("cannot write to standard output: %1").arg(why)
                     : QStringLiteral("%1: cannot write %2: %3").arg(path_, what_, why);
    }
    return false;
}

QString OutputFile::reason(qint64 written, qint64 wanted) const {
    const QFileDevice* device = saveFile_ ? static_cast<const QFileDevice*>(saveFile_.get())
                                          : static_cast<const QFileDevice*>(direct_.get());
    if (device && device->error() != QFileDevice::NoError) return device->errorString();
    if (written >= 0 && wanted > 0)
        return QStringLiteral("only %1 of %2 bytes could be written (is the disk full?)")
            .arg(written)
            .arg(wanted);
    return QStringLiteral("the write failed");
}

}  // namespace phasebox
