#pragma once
// One input of the app's open-and-save fuzzer (fuzz_scene_files.cpp): what File → Open and
// File → Save do with it, through the Document the desktop app uses (SceneFiles calls
// Document::load and Document::save). The first byte chooses what the file is: mostly a
// regular file holding the rest of the input, sometimes a FIFO, a device or a folder, which
// must be refused at once (the fuzzer's timeout catches an open that blocks).
// Shared with the replay in tests/app/tst_fuzz_corpus.cpp.
//
// The promises, the first one broken returned in words:
//   - a refused open names the file and leaves the open document exactly as it was;
//   - an accepted scene saves to a new file, which opens again to the same scene, and saves
//     over its own file (the save-in-place path), which loads again too;
//   - a save onto a full device fails with the path and the system's reason, leaves the
//     device a device and the document modified and on its old path.

#include "app/document/Document.h"
#include "app/io/SceneIO.h"
#include "tests/support/OutputTargets.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>

#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>

namespace phasebox::fuzz {

// *accepted (when given) tells whether the file opened, for a replay to see which paths its
// seeds take.
inline QString checkSceneFilesInput(const std::uint8_t* data, std::size_t size, const QString& root,
                                    bool* accepted = nullptr) {
    QDir(root).removeRecursively();
    if (!QDir().mkpath(root)) return {};
    const QString path = root + QStringLiteral("/opened.phasebox.json");
    const int kind = size > 0 ? data[0] % 16 : 0;
    const QByteArray bytes =
        size > 0 ? QByteArray(reinterpret_cast<const char*>(data) + 1, qsizetype(size - 1))
                 : QByteArray();
    QString opened = path;
    if (kind == 13) {
        if (::mkfifo(QFile::encodeName(path).constData(), 0644) != 0) return {};
    } else if (kind == 14) {
        opened = QStringLiteral("/dev/zero");
    } else if (kind == 15) {
        opened = root;
    } else {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size()) return {};
    }

    Document document;
    const QByteArray before = SceneIO::serialize(document.setup());
    const QString pathBefore = document.filePath();
    QString error;
    const bool loaded = document.load(opened, &error);
    if (accepted) *accepted = loaded;
    if (!loaded) {
        if (error.isEmpty()) return QStringLiteral("an open was refused without a message");
        if (!error.startsWith(opened + QLatin1Char(':')))
            return QStringLiteral("a refused open does not name the file: ") + error.left(300);
        if (SceneIO::serialize(document.setup()) != before || document.filePath() != pathBefore)
            return QStringLiteral("a refused open changed the open document");
        return {};
    }
    if (kind >= 13) return QStringLiteral("a FIFO, device or folder was opened as a scene");

    const QByteArray setup = SceneIO::serialize(document.setup());
    const QString copy = root + QStringLiteral("/saved.phasebox.json");
    if (!document.save(copy, &error))
        return QStringLiteral("saving an opened scene failed: ") + error.left(300);
    Document reopened;
    if (!reopened.load(copy, &error))
        return QStringLiteral("a saved scene does not open: ") + error.left(300);
    if (SceneIO::serialize(reopened.setup()) != setup)
        return QStringLiteral("a saved scene opens as a different scene");
    if (!reopened.save(copy, &error) || !reopened.load(copy, &error))
        return QStringLiteral("saving over its own file failed: ") + error.left(300);

    const QString full = root + QStringLiteral("/full.phasebox.json");
    // A private node where mknod is allowed, else a link to /dev/full: the case always runs.
    if (!testing::makeDevice(full, testing::SystemDevice::Full))
        return QStringLiteral("could not make a full device at ") + full;
    {
        // An unsaved edit first, when the scene takes one: it must stay unsaved.
        ParticleDesc probe;
        probe.id = "fuzz-unsaved-edit";
        reopened.addObject(probe);
        const bool modified = reopened.isModified();
        const QString filePath = reopened.filePath();
        if (reopened.save(full, &error))
            return QStringLiteral("a save onto a full device reported success");
        if (error != full + QStringLiteral(": cannot write the file: No space left on device"))
            return QStringLiteral("a failed save says: ") + error.left(300);
        if (!testing::isStillDevice(full, testing::SystemDevice::Full))
            return QStringLiteral("a save replaced the device");
        if (reopened.isModified() != modified || reopened.filePath() != filePath)
            return QStringLiteral("a failed save changed the document's state");
    }
    return {};
}

}  // namespace phasebox::fuzz
