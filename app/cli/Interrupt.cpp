#include "app/cli/Interrupt.h"

#include <csignal>

#if defined(__unix__) || defined(__APPLE__)
#include <signal.h>
#define PHASEBOX_POSIX_SIGNALS 1
#endif

namespace phasebox::cli {

namespace {

// Lock-free, so a signal handler may store to it (a plain sig_atomic_t could not be handed to
// runAccuracyStudy's cancel flag).
std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void onInterrupt(int) {
    gInterrupted.store(true, std::memory_order_relaxed);
}

#if PHASEBOX_POSIX_SIGNALS
struct sigaction gPreviousInt {
}, gPreviousTerm{};
#endif

}  // namespace

InterruptGuard::InterruptGuard() {
    gInterrupted.store(false);
#if PHASEBOX_POSIX_SIGNALS
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    // One-shot: the first signal asks for a clean stop, a second one ends the program at once.
    // SA_RESTART: system calls under way carry on (not every library retries after EINTR).
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    ::sigaction(SIGINT, &action, &gPreviousInt);
    ::sigaction(SIGTERM, &action, &gPreviousTerm);
#else
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
#endif
}

InterruptGuard::~InterruptGuard() {
#if PHASEBOX_POSIX_SIGNALS
    ::sigaction(SIGINT, &gPreviousInt, nullptr);
    ::sigaction(SIGTERM, &gPreviousTerm, nullptr);
#else
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
#endif
}

bool InterruptGuard::interrupted() {
    return gInterrupted.load(std::memory_order_relaxed);
}

const std::atomic<bool>& InterruptGuard::flag() {
    return gInterrupted;
}

}  // namespace phasebox::cli
