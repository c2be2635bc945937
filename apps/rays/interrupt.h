// Ctrl-C (SIGINT) and SIGTERM during a render: the first signal asks the render to stop (workers
// finish their tile, no new tile starts, see rays::setCancelFlag); the pipeline checks between its
// phases, writes no output and exits with 128 + the signal (130 for Ctrl-C). A second signal exits
// at once, except while an image is being written (the atomic write then completes first).
#pragma once
#include <exception>
#include <string>

namespace rays::cli {

/// Thrown at a checkpoint after a signal; main() prints the message and returns exitStatus().
class Interrupted : public std::exception {
public:
    explicit Interrupted(int signal) : signal_(signal) {}
    int signal() const { return signal_; }
    int exitStatus() const { return 128 + signal_; }
    const char* what() const noexcept override { return "interrupted"; }

private:
    int signal_;
};

/// While alive: SIGINT and SIGTERM are caught (and the renderer's cancel flag points at ours);
/// the previous handlers are restored on destruction. Scopes nest (the animation loop holds one
/// around each frame's): only the outermost one installs the handlers and clears the signal state,
/// so a signal between two frames is still seen. Main thread only.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
};

/// While alive (inside an InterruptScope), the first signal ends the process at once, with the
/// messages and the exit status of a stop at a checkpoint: for phases that write nothing and run
/// code that does not look at the flag (loading the scene, its OBJ files and textures, building
/// the BVH). Main thread only.
class QuitAtOnce {
public:
    QuitAtOnce();  ///< throws Interrupted when a signal already arrived
    ~QuitAtOnce();
    QuitAtOnce(const QuitAtOnce&) = delete;
    QuitAtOnce& operator=(const QuitAtOnce&) = delete;
};

/// Called first by the signal handler with the signal (so it must be async-signal-safe): the MPI
/// run names a rank that died there (apps/rays/mpi/mpi_lost_rank.h). Returning true silences the
/// interrupt messages from then on (another line has said what happened, or another rank speaks).
using SignalHook = bool (*)(int signal);
void setSignalHook(SignalHook hook);

/// True once a SignalHook asked for silence: main() then leaves out its "interrupted" line.
bool interruptMessagesMuted();

/// True once a signal arrived inside an InterruptScope.
bool interrupted();
/// Throws Interrupted when interrupted().
void throwIfInterrupted();

/// While alive, a second signal does not exit at once (it is remembered like the first): used
/// around writing the image files so a signal never leaves a temporary file behind.
class CriticalSection {
public:
    CriticalSection();
    ~CriticalSection();
    CriticalSection(const CriticalSection&) = delete;
    CriticalSection& operator=(const CriticalSection&) = delete;
};

/// The partial image's path: OUTPUT with its extension replaced by ".partial.png"
/// ("out.jpg" -> "out.partial.png", "dir/a.b.png" -> "dir/a.b.partial.png").
std::string partialImagePath(const std::string& output);

}  // namespace rays::cli
