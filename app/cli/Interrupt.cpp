#include "app/cli/Interrupt.h"

#include <csignal>

#if defined(__unix__) || defined(__APPLE__)
#include <signal.h>
#include <time.h>
#define PHASEBOX_POSIX_SIGNALS 1
#endif

namespace phasebox::cli {

namespace {

// Lock-free, so a signal handler may store to it (a plain sig_atomic_t could not be handed to
// runAccuracyStudy's cancel flag).
std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

#if PHASEBOX_POSIX_SIGNALS
// When the first signal came (CLOCK_MONOTONIC, ns): a second one within kRepeatNs is the same
// request delivered twice (GNU timeout signals the child and then its process group), a later
// one is the user's second Ctrl-C and ends the program at once.
std::atomic<long long> gFirstNs{0};
static_assert(std::atomic<long long>::is_always_lock_free);
constexpr long long kRepeatNs = 500'000'000;

long long monotonicNs() {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);  // async-signal-safe (POSIX)
    return static_cast<long long>(ts.tv_sec) * 1'000'000'000LL + ts.tv_nsec;
}
#endif

extern "C" void onInterrupt(int signal) {
#if PHASEBOX_POSIX_SIGNALS
    const long long now = monotonicNs();
    if (gInterrupted.load(std::memory_order_relaxed)) {
        if (now - gFirstNs.load(std::memory_order_relaxed) < kRepeatNs) return;
        ::signal(signal, SIG_DFL);
        ::raise(signal);
        return;
    }
    gFirstNs.store(now, std::memory_order_relaxed);
#else
    (void)signal;
#endif
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
    // The first signal asks for a clean stop; a second one half a second later or more ends
    // the program at once (onInterrupt). SA_RESTART: system calls under way carry on (not every
    // library retries after EINTR).
    action.sa_flags = SA_RESTART;
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
