#pragma once
// Ctrl-C and SIGTERM during `phasebox-cli run` and `accuracy` (CONTRACT.md §4): the step in
// progress finishes, the results so far are written, and the exit status is 130.
//
// While an InterruptGuard lives, SIGINT and SIGTERM only set a flag that the step loop reads
// between steps; a second signal ends the program at once (the handler is one-shot), so a
// person who presses Ctrl-C twice is never kept waiting.

#include <atomic>

namespace phasebox::cli {

class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // Whether SIGINT or SIGTERM arrived since the guard was made.
    static bool interrupted();
    // The flag itself, for code that takes a cancel flag (runAccuracyStudy).
    static const std::atomic<bool>& flag();
};

}  // namespace phasebox::cli
