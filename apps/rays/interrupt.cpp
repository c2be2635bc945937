#include "interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>

#include "rays/render/renderer.h"

namespace rays::cli {
namespace {

// Everything the handler touches is a lock-free atomic (async-signal-safe).
std::atomic<bool> stopRequested{false};
std::atomic<int> signalCount{0};
std::atomic<int> lastSignal{0};
std::atomic<int> criticalDepth{0};
std::atomic<int> quitAtOnceDepth{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

std::atomic<SignalHook> signalHook{nullptr};
std::atomic<bool> messagesMuted{false};

struct sigaction previousInt, previousTerm;
int scopeDepth = 0;  // InterruptScopes alive (main thread only); the outermost one owns the handlers

void say(const char* text) {
    size_t n = 0;
    while (text[n]) ++n;
    ssize_t ignored = ::write(STDERR_FILENO, text, n);
    (void)ignored;
}

extern "C" void onSignal(int sig) {
    lastSignal.store(sig);
    stopRequested.store(true);
    const SignalHook hook = signalHook.load();
    if (hook && hook(sig)) messagesMuted.store(true);
    const bool quiet = messagesMuted.load();
    if (signalCount.fetch_add(1) == 0) {
        if (!quiet) say("\nrays: interrupted: stopping (signal again to quit at once)\n");
        if (quitAtOnceDepth.load() > 0 && criticalDepth.load() == 0) {
            if (!quiet) say("rays: interrupted; no image written\n");
            ::_exit(128 + sig);
        }
    } else if (criticalDepth.load() == 0) {
        if (!quiet) say("rays: interrupted again: quitting\n");
        ::_exit(128 + sig);
    }
}

}  // namespace

InterruptScope::InterruptScope() {
    if (scopeDepth++ > 0) return;  // nested (a frame inside an animation): the outer scope's state holds
    stopRequested.store(false);
    signalCount.store(0);
    lastSignal.store(0);
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &sa, &previousInt);
    ::sigaction(SIGTERM, &sa, &previousTerm);
    setCancelFlag(&stopRequested);
}

InterruptScope::~InterruptScope() {
    if (--scopeDepth > 0) return;
    setCancelFlag(nullptr);
    ::sigaction(SIGINT, &previousInt, nullptr);
    ::sigaction(SIGTERM, &previousTerm, nullptr);
}

bool interrupted() { return stopRequested.load(); }

void setSignalHook(SignalHook hook) { signalHook.store(hook); }

bool interruptMessagesMuted() { return messagesMuted.load(); }

void throwIfInterrupted() {
    if (stopRequested.load()) throw Interrupted(lastSignal.load() ? lastSignal.load() : SIGINT);
}

QuitAtOnce::QuitAtOnce() {
    quitAtOnceDepth.fetch_add(1);
    if (stopRequested.load()) {
        quitAtOnceDepth.fetch_sub(1);
        throwIfInterrupted();
    }
}
QuitAtOnce::~QuitAtOnce() { quitAtOnceDepth.fetch_sub(1); }

CriticalSection::CriticalSection() { criticalDepth.fetch_add(1); }
CriticalSection::~CriticalSection() { criticalDepth.fetch_sub(1); }

std::string partialImagePath(const std::string& output) {
    const size_t slash = output.find_last_of('/');
    const size_t dot = output.find_last_of('.');
    const bool hasExt = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (hasExt ? output.substr(0, dot) : output) + ".partial.png";
}

}  // namespace rays::cli
