#pragma once
// The one way Phasebox opens a file to read it (scenes, the autosave and its sidecar, the
// settings file): never blocking and never unbounded. A FIFO would block the open until
// someone writes to it, and a device such as /dev/zero or /dev/urandom (or a link to one)
// would be read for ever, so the file is opened without blocking, its type is checked on the
// open descriptor (no gap for it to be swapped between a check and the open), and at most a
// given number of bytes is read.

#include <QByteArray>
#include <QString>

QT_BEGIN_NAMESPACE
class QFile;
QT_END_NAMESPACE

namespace phasebox::inputfile {

// Opens path for reading if it is a regular file (or a built-in :/ resource); otherwise
// returns "cannot read the file: REASON" ("it is a FIFO (named pipe), not a KIND", "it is a
// device, not a KIND", "it is a folder", the system's reason) and leaves file closed.
QString open(const QString& path, QFile& file, const QString& kind = QStringLiteral("scene file"));

// What path is when it exists and is not a regular file ("a FIFO (named pipe)", "a device",
// "a folder", "a socket", "not a regular file"), following links, without opening it; empty
// for a regular file or a name that does not exist.
QString irregularKind(const QString& path);

// Opens (as above) and reads the whole file into *bytes when it holds at most maxBytes;
// otherwise false with *error "PATH: REASON" (the reasons above, or "the file is larger
// than N bytes").
bool readAll(const QString& path, qint64 maxBytes, QByteArray* bytes, QString* error,
             const QString& kind = QStringLiteral("scene file"));

}  // namespace phasebox::inputfile
