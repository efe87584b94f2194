#pragma once
// Scene files (CONTRACT.md §1): JSON ⇄ SceneDesc, with the contract's validation messages.
// Loading never throws, never blocks on a FIFO or device, and never touches anything but its
// result; saving goes through OutputFile so that a failed or interrupted save leaves the old
// file intact.

#include "physics/scene/SceneDesc.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace phasebox {

struct SceneLoadResult {
    std::optional<SceneDesc> scene;  // set on success
    // On failure, one line per problem, each naming the file, the place (line:column for a
    // syntax error, a JSON path such as boxes[3].size[0] otherwise) and what is wrong:
    //   "lesson.json:4:17: unterminated string"
    //   "lesson.json: boxes[3].size[0]: must be > 0 (got -1)"
    QStringList errors;

    bool ok() const { return scene.has_value(); }
    QString errorText() const { return errors.join(QLatin1Char('\n')); }
};

class SceneIO {
public:
    // Reads and parses a file. sourceName in messages is the file name as given.
    static SceneLoadResult load(const QString& path);
    // Parses JSON text; sourceName is used in the messages only.
    static SceneLoadResult parse(const QByteArray& json, const QString& sourceName);

    // Scene format v1, pretty-printed, every field written (defaults included) so that a file
    // says what the scene is; load → save → load gives the identical scene.
    static QByteArray serialize(const SceneDesc& scene);
    // Writes through OutputFile (QSaveFile for a regular file, in place for a device or FIFO).
    // On failure returns false, sets *error ("PATH: cannot write the file: REASON"), and the
    // old file (if any) is untouched.
    static bool save(const SceneDesc& scene, const QString& path, QString* error);
};

}  // namespace phasebox
