#include "app/cli/Interrupt.h"

#include "app/io/OutputFile.h"

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

}  // namespace

void installInterruptHandlers() {
#if PHASEBOX_POSIX_SIGNALS
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    // No SA_RESTART: a write() blocked on a pipe nobody reads (`| sleep 1000`) returns EINTR,
    // and OutputFile, seeing the flag, abandons it (exit 130) instead of blocking for ever.
    action.sa_flags = 0;
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        // A signal ignored by whoever started us (nohup, a shell's background job) stays ignored.
        struct sigaction previous {};
        if (::sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN)
            continue;
        ::sigaction(signal, &action, nullptr);
    }
#else
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
#endif
    OutputFile::setInterruptFlag(&gInterrupted);
}

bool interrupted() {
    return gInterrupted.load(std::memory_order_relaxed);
}

const std::atomic<bool>& interruptFlag() {
    return gInterrupted;
}

}  // namespace phasebox::cli
