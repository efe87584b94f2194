#pragma once
// Ctrl-C, SIGTERM and SIGHUP in phasebox-cli (CONTRACT.md §4): the step in progress finishes,
// the results so far are written, and the exit status is 130.
//
// installInterruptHandlers() is the first thing main() does, so a signal that comes while the
// scene loads is not lost (installed later, a Ctrl-C while loading would kill the program with
// nothing written). The first signal only
// sets a flag that the commands read (after loading, after building, between steps); a second
// one half a second or more later ends the program at once. The handlers are installed without
// SA_RESTART, so a write blocked on a full pipe returns EINTR and the output layer
// (OutputFile, which reads the same flag) gives up on it instead of waiting for ever.

#include <atomic>

namespace phasebox::cli {

// Installs the handlers of SIGINT, SIGTERM and SIGHUP and hands the flag to OutputFile.
void installInterruptHandlers();

// Whether SIGINT, SIGTERM or SIGHUP arrived since the program started.
bool interrupted();
// The flag itself, for code that takes a cancel flag (runAccuracyStudy).
const std::atomic<bool>& interruptFlag();

}  // namespace phasebox::cli
