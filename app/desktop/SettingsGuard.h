#pragma once
// The user's settings files, checked before the first QSettings reads them.

#include <QStringList>

namespace phasebox {

// QSettings opens and reads its file with no bound: a FIFO there blocks the start for ever, and
// a link to /dev/zero is read until memory runs out. So before the first QSettings, the user's
// settings files (Qt's names for them: ORGANIZATION/APPLICATION.conf and ORGANIZATION.conf in
// the generic config folder) are checked without being opened: one that is not a regular file
// is removed (a link, not its target), and one larger than 1 MiB (ours hold a few kilobytes)
// is moved aside as NAME.too-large. Says what was done in *problems, one line each; false when
// a file that must not be read is still there (then no QSettings may be made). With repair
// false nothing is changed: the answer is only whether the files may be read as they are.
bool guardSettingsFiles(QStringList* problems, bool repair = true);

}  // namespace phasebox
