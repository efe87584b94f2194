#pragma once
// The one writer of every file Phasebox writes: scenes, the autosave, CSV, JSON, PNG and SVG,
// from the app and from phasebox-cli (CONTRACT.md §4: "an earlier file of that name is kept
// whole").
//
// - A regular file (or a name that does not exist yet) is written through QSaveFile: the
//   contents go to a temporary file in the same folder, which replaces the old file only
//   when every byte is written and closed. A failure leaves the earlier file as it was.
// - A device, a FIFO or a socket (or anything under /dev or /proc, such as /dev/stdout), and
//   "-" for standard output, is written in place: renaming a finished file over /dev/null or
//   over a pipe someone reads from would replace it with a regular file.
// - Every write, the flush and the close are checked. A failure gives
//   "PATH: cannot write WHAT: REASON" with the system's reason ("No space left on device",
//   "File too large").

#include <QByteArray>
#include <QString>

#include <atomic>
#include <memory>

QT_BEGIN_NAMESPACE
class QIODevice;
class QFile;
class QSaveFile;
QT_END_NAMESPACE

namespace phasebox {

class OutputFile {
public:
    // what names the file in messages: "the file", "the CSV file", "the plot".
    explicit OutputFile(QString path, QString what = QStringLiteral("the file"));
    // An open, uncommitted regular file is abandoned: its temporary copy is removed and the
    // earlier file stays.
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    // Standard output: "-", "/dev/stdout", and any path that leads to the very file, pipe or
    // socket standard output is (/proc/self/fd/1, a link to it, the file `> out.csv` opened).
    // Opened again by name, such a path would write from offset 0 and the summary would
    // overwrite the CSV's head.
    static bool isStandardOutput(const QString& path);
    // Why path cannot be written at all (a loop of symbolic links), or an empty string.
    static QString unusablePath(const QString& path);
    // The flag that SIGINT, SIGTERM and SIGHUP set (phasebox-cli). When it is set, a write
    // that the signal interrupted (EINTR), or one that cannot go on within a second, is
    // abandoned as interrupted() instead of blocking for ever on a pipe nobody reads.
    static void setInterruptFlag(const std::atomic<bool>* flag);
    // Whether two paths name the same existing file (the same device and inode, so links and
    // different spellings count); false when either does not exist.
    static bool sameFile(const QString& a, const QString& b);
    // Opens, writes and commits in one call; false with *error set on failure.
    static bool writeAll(const QString& path, const QByteArray& bytes, QString* error,
                         const QString& what = QStringLiteral("the file"));

    bool open();
    // The device to write to (a QTextStream may be put on it), valid after open().
    QIODevice* device() const;
    // Writes every byte or records the failure; false once anything has failed.
    bool write(const QByteArray& bytes);
    // Flushes and closes; for a regular file, puts the new file in place of the old one.
    // False when anything failed since open(), with error() set.
    bool commit();
    // Abandons the output (a regular file keeps its earlier contents).
    void cancel();

    bool failed() const { return !error_.isEmpty(); }
    // Whether the output was abandoned because of an interrupting signal (exit 130, not 3).
    bool interrupted() const { return interrupted_; }
    // "PATH: cannot write WHAT: REASON", or empty.
    const QString& error() const { return error_; }
    const QString& path() const { return path_; }
    // Written in place (a device, a FIFO, standard output) rather than through a temporary file.
    bool inPlace() const { return inPlace_; }

private:
    // The file or device written to (checked_ forwards to it).
    QIODevice* target() const;
    bool fail(const QString& reason);
    // The device's error text, or a short write's description when it set none.
    QString reason(qint64 written = -1, qint64 wanted = -1) const;
    // Writes in place with write(2), retrying after a signal unless it asked to stop.
    bool writeDirect(const char* data, qint64 size);

    QString path_;
    QString what_;
    std::unique_ptr<QSaveFile> saveFile_;
    std::unique_ptr<QFile> direct_;
    std::unique_ptr<QIODevice> checked_;
    bool inPlace_ = false;
    bool open_ = false;
    bool interrupted_ = false;
    QString error_;
};

}  // namespace phasebox
