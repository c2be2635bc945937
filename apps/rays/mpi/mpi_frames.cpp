#include "mpi_frames.h"

#include <mpi.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "../interrupt.h"
#include "../paths.h"
#include "mpi_lost_rank.h"
#include "mpi_session.h"
#include "mpi_summary.h"
#include "mpi_wait.h"
#include "rays/error.h"

namespace rays::cli::mpi {
namespace {

using FrameClock = std::chrono::steady_clock;

// Messages: a rank's report (tag kFrameReport, a FrameReport) after each frame (frame -1: none
// yet), answered by rank 0 with the next frame's index in the plan (kFrameAssign, -1: no more).
constexpr int kFrameReport = 11, kFrameAssign = 12;

struct FrameReport {
    int32_t frame = -1;
    int32_t rank = 0;
    double seconds = 0;
    RenderFigures figures;
};

double secondsFrom(FrameClock::time_point t0) { return std::chrono::duration<double>(FrameClock::now() - t0).count(); }

// Renders frame i of plan alone in this process, quietly (rank 0 reports for all).
FrameReport renderWholeFrame(const RenderJob& base, const FramePlan& plan, int i, const FrameRenderer& render,
                             int& status) {
    RenderJob job = frameJob(base, plan, size_t(i));
    job.alone = true;
    job.quiet = true;
    job.summary = false;
    FrameReport r;
    r.frame = i;
    r.rank = rank();
    job.figures = &r.figures;
    const auto t0 = FrameClock::now();
    status = render(job);
    r.seconds = secondsFrom(t0);
    return r;
}

void addTo(RankFigures& f, const FrameReport& r) {
    f.parseBuild += r.figures.parseBuildMs / 1000;
    f.render += r.figures.renderMs / 1000;
    f.write += r.figures.writeMs / 1000;
    f.busy += r.seconds;
    f.rays += r.figures.rays;
}

// The frames rank 0 hands out: all of the plan, less those --resume finds written.
std::vector<int> framesToRender(const RenderJob& base, const FramePlan& plan, bool resume) {
    std::vector<int> todo;
    for (size_t i = 0; i < plan.frames.size(); ++i) {
        const std::string out = frameJob(base, plan, i).outputPath;
        if (resume && fileExists(out)) {
            if (!base.quiet)
                std::fprintf(stderr, "rays: %s: %s exists; skipped (resume)\n", frameLabel(plan, i).c_str(),
                             printableMessage(out).c_str());
            continue;
        }
        todo.push_back(int(i));
    }
    return todo;
}

// Rank 0's lines: one per frame written and, on a terminal, a bar over all frames under them.
class FrameLog {
public:
    FrameLog(const RenderJob& base, const FramePlan& plan, size_t total)
        : base_(base), plan_(plan), total_(total), bar_(!base.quiet && isatty(STDERR_FILENO)) {
        draw();
    }
    void written(const FrameReport& r) {
        ++done_;
        if (base_.quiet) return;
        if (bar_) std::fprintf(stderr, "\r%60s\r", "");
        std::fprintf(stderr, "rays: %s: wrote %s on rank %d in %.2f s\n", frameLabel(plan_, size_t(r.frame)).c_str(),
                     printableMessage(frameJob(base_, plan_, size_t(r.frame)).outputPath).c_str(), r.rank, r.seconds);
        draw();
    }
    size_t done() const { return done_; }
    ~FrameLog() {
        if (bar_) std::fprintf(stderr, "\r%60s\r", "");
    }

private:
    void draw() {
        if (!bar_ || total_ == 0) return;
        const int width = 30, filled = int(double(done_) / double(total_) * width + 0.5);
        std::fprintf(stderr, "\rframes [%-*s] %zu of %zu ", width, std::string(size_t(filled), '#').c_str(), done_, total_);
        std::fflush(stderr);
    }
    const RenderJob& base_;
    const FramePlan& plan_;
    size_t total_, done_ = 0;
    bool bar_;
};

// A rank other than 0: reports, takes the next frame, renders it, until rank 0 says no more.
RankFigures serveFrames(const RenderJob& base, const FramePlan& plan, const FrameRenderer& render) {
    RankFigures mine;
    FrameReport report;
    report.rank = rank();
    dieIfTestAsks();
    for (;;) {
        sendGently(&report, sizeof report, MPI_BYTE, 0, kFrameReport);
        int i = -1;
        recvGently(&i, 1, MPI_INT, 0, kFrameAssign);
        if (i < 0) return mine;
        int status = 0;
        report = renderWholeFrame(base, plan, i, render, status);
        if (status != 0) throw Error("rays: error: rank " + std::to_string(rank()) + ": frame " +
                                     std::to_string(plan.frames[size_t(i)].frameNumber) + " failed (exit status " +
                                     std::to_string(status) + ")");
        addTo(mine, report);
    }
}

// What rank 0's own render thread leaves behind.
struct LocalFrames {
    std::mutex lock;
    std::vector<FrameReport> written;  // not yet announced
    std::exception_ptr failure;
    int status = 0;
    std::atomic<bool> finished{false};
    RankFigures figures;
};

// Rank 0's render thread: takes frames from next until none is left or one fails.
void renderLocalFrames(const RenderJob& base, const FramePlan& plan, const std::vector<int>& todo,
                       std::atomic<size_t>& next, const FrameRenderer& render, LocalFrames& out) {
    try {
        for (size_t k = next.fetch_add(1); k < todo.size(); k = next.fetch_add(1)) {
            int status = 0;
            const FrameReport r = renderWholeFrame(base, plan, todo[k], render, status);
            if (status != 0) {
                out.status = status;
                break;
            }
            addTo(out.figures, r);
            std::lock_guard<std::mutex> g(out.lock);
            out.written.push_back(r);
        }
    } catch (...) {
        out.failure = std::current_exception();
    }
    out.finished.store(true);
}

void announceLocal(LocalFrames& local, FrameLog& log) {
    std::vector<FrameReport> reports;
    {
        std::lock_guard<std::mutex> g(local.lock);
        reports.swap(local.written);
    }
    for (const FrameReport& r : reports) log.written(r);
}

// Rank 0: hands out the frames, renders some itself, announces each one written. Returns rank
// 0's figures; throws what its own frames threw.
RankFigures leadFrames(const RenderJob& base, const FramePlan& plan, const std::vector<int>& todo,
                       const FrameRenderer& render, int& status) {
    std::atomic<size_t> next{0};
    LocalFrames local;
    FrameLog log(base, plan, todo.size());
    std::jthread worker([&] { renderLocalFrames(base, plan, todo, next, render, local); });
    int active = size() - 1;
    while (active > 0 && !(local.finished.load() && (local.failure || local.status)) && !interrupted()) {
        announceLocal(local, log);
        int ready = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, kFrameReport, MPI_COMM_WORLD, &ready, &st);
        if (!ready) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));  // the render threads need the cores
            continue;
        }
        FrameReport r;
        MPI_Recv(&r, sizeof r, MPI_BYTE, st.MPI_SOURCE, kFrameReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (r.frame >= 0) log.written(r);
        const size_t k = next.fetch_add(1);
        int assign = k < todo.size() ? todo[k] : -1;
        if (assign < 0) --active;
        MPI_Send(&assign, 1, MPI_INT, st.MPI_SOURCE, kFrameAssign, MPI_COMM_WORLD);
    }
    if (interrupted()) next.store(todo.size());  // the render thread takes no further frame
    worker.join();
    announceLocal(local, log);
    if (local.failure) std::rethrow_exception(local.failure);
    throwIfInterrupted();
    status = local.status;
    return local.figures;
}

}  // namespace

int runFramesOnRanks(const RenderJob& base, const FramePlan& plan, bool resume, const FrameRenderer& render) {
    InterruptScope interruptScope;  // one scope around all frames: a signal between frames is seen
    const auto t0 = FrameClock::now();
    int status = 0;
    RankFigures mine;
    size_t frames = 0;
    try {
        if (rank() == 0) {
            const std::vector<int> todo = framesToRender(base, plan, resume);
            frames = todo.size();
            mine = leadFrames(base, plan, todo, render, status);
        } else {
            mine = serveFrames(base, plan, render);
        }
    } catch (const Interrupted& e) {
        if (rank() == 0)
            std::fprintf(stderr, "rays: stopped: the frames being rendered are not written; run again with --resume to render the rest\n");
        return e.exitStatus();
    }
    if (status != 0) return status;  // finish() stops the other ranks
    barrierGently();  // the ranks done first sleep until the last one is
    const std::vector<RankFigures> all = gatherFigures(mine);
    if (rank() == 0 && !base.quiet) {
        JobPhases phases;
        for (const RankFigures& r : all) phases.parseBuild += r.parseBuild, phases.render += r.render, phases.write += r.write;
        std::fprintf(stderr, "%s\n", summaryLine(all, phases, hostCount(), int(frames), secondsFrom(t0)).c_str());
    }
    return 0;
}

}  // namespace rays::cli::mpi
