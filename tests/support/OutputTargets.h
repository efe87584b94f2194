#pragma once
// Targets that are not plain files, for the suites that check how outputs are written
// (tests/app/tst_output_file, tests/cli/tst_cli_outputs): a device that behaves as /dev/full
// or /dev/null under a name the test chooses, FIFOs and a reader for them, and the checks that
// such a target is still what the test put there.

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QString>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cstdlib>
#include <thread>

namespace phasebox::testing {

inline QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

// Without following a link: a link to a device is not the device.
inline bool isCharDevice(const QString& path) {
    struct stat st {};
    return ::lstat(QFile::encodeName(path).constData(), &st) == 0 && S_ISCHR(st.st_mode);
}

inline bool isFifo(const QString& path) {
    struct stat st {};
    return ::lstat(QFile::encodeName(path).constData(), &st) == 0 && S_ISFIFO(st.st_mode);
}

// The two system devices the suites write to; the value is the minor number (major 1).
enum class SystemDevice : unsigned { Null = 3, Full = 7 };

inline QString systemDevicePath(SystemDevice device) {
    return device == SystemDevice::Full ? QStringLiteral("/dev/full") : QStringLiteral("/dev/null");
}

// Set PHASEBOX_TEST_SYSTEM_DEVICES=1 to take the fallback below even where mknod works, to
// check it on a machine that runs the suites as root.
inline bool privateDeviceNodesAllowed() {
    const char* force = std::getenv("PHASEBOX_TEST_SYSTEM_DEVICES");
    return force == nullptr || QByteArray(force) != "1";
}

namespace detail {

inline bool isThatDevice(const QString& path, SystemDevice device) {
    struct stat st {};
    return ::lstat(QFile::encodeName(path).constData(), &st) == 0 && S_ISCHR(st.st_mode) &&
           st.st_rdev == makedev(1, static_cast<unsigned>(device));
}

}  // namespace detail

// Puts at path (which must not exist) a device that behaves as /dev/full or /dev/null, so a
// test can write to it under the name it needs (a plot must end in .png, the autosave picks
// its own file name). A private node where mknod is allowed (root): if the program wrongly
// replaced it by a regular file, no system device is harmed and the test sees it. Elsewhere a
// symbolic link to the system's own device, which the program follows like any user's path:
// the writes reach the real device and fail (or vanish) the same way. Where mknod is refused
// /dev is not writable either, so a program that wrongly tried to replace the device through
// the link would fail with "Permission denied" (and the test with it) instead of replacing it.
// False only if neither could be made.
inline bool makeDevice(const QString& path, SystemDevice device) {
    const QByteArray name = QFile::encodeName(path);
    if (privateDeviceNodesAllowed() &&
        ::mknod(name.constData(), S_IFCHR | 0666, makedev(1, static_cast<unsigned>(device))) == 0)
        return true;
    return ::symlink(QFile::encodeName(systemDevicePath(device)).constData(), name.constData()) ==
           0;
}

// Whether path is still what makeDevice put there (the check that the program did not put a
// regular file in its place): the private node, with its numbers, or the link, unchanged, to a
// system device that is itself still that device.
inline bool isStillDevice(const QString& path, SystemDevice device) {
    if (detail::isThatDevice(path, device)) return true;
    struct stat st {};
    if (::lstat(QFile::encodeName(path).constData(), &st) != 0 || !S_ISLNK(st.st_mode))
        return false;
    const QString target = systemDevicePath(device);
    return QFile::symLinkTarget(path) == target && detail::isThatDevice(target, device);
}

inline bool makeFifo(const QString& path) {
    return ::mkfifo(QFile::encodeName(path).constData(), 0644) == 0;
}

// Reads a FIFO to its end in a thread (a write to a FIFO waits for a reader). Opened without
// blocking and polled with a deadline of 30 s, so that a program that never writes to it (one
// that renamed a regular file over it) fails the test instead of hanging it.
class FifoReader {
public:
    explicit FifoReader(const QString& path)
        : thread_([this, path] {
              const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK);
              if (fd < 0) return;
              QElapsedTimer timer;
              timer.start();
              bool writerSeen = false;
              while (timer.elapsed() < 30000) {
                  pollfd p{fd, POLLIN, 0};
                  if (::poll(&p, 1, 100) <= 0) continue;
                  char buffer[65536];
                  const ssize_t n = ::read(fd, buffer, sizeof buffer);
                  if (n > 0) {
                      bytes_.append(buffer, n);
                      writerSeen = true;
                  } else if (n == 0 && (writerSeen || (p.revents & POLLHUP))) {
                      break;  // the writer closed its end
                  } else if (n == 0) {
                      ::usleep(10000);  // no writer yet
                  }
              }
              ::close(fd);
          }) {}
    FifoReader(const FifoReader&) = delete;
    FifoReader& operator=(const FifoReader&) = delete;
    ~FifoReader() {
        if (thread_.joinable()) thread_.join();
    }

    // Waits for the writer to finish (or the deadline) and gives what was read.
    QByteArray take() {
        thread_.join();
        return bytes_;
    }

private:
    QByteArray bytes_;
    std::thread thread_;
};

}  // namespace phasebox::testing
