#include "animation.h"

#include <chrono>
#include <cstdio>
#include <string>

#include "rays/error.h"
#include "interrupt.h"
#include "paths.h"

namespace rays::cli {

std::string frameLabel(const FramePlan& plan, size_t i) {
    const sdl::AnimationClock& c = plan.frames[i];
    char text[160];
    std::snprintf(text, sizeof text, "frame %zu of %zu (frame_number %d, clock %.6g)", i + 1, plan.frames.size(),
                  c.frameNumber, c.clock);
    return text;
}

RenderJob frameJob(const RenderJob& base, const FramePlan& plan, size_t i) {
    RenderJob job = base;
    job.language.animation = plan.frames[i];
    if (plan.animated) {
        job.outputPath = frameFileName(base.outputPath, plan.frames[i].frameNumber, plan.digits);
        // Each frame's edge mask is numbered as its image is, not written over the last frame's.
        if (!base.edges.maskPath.empty())
            job.edges.maskPath = frameFileName(base.edges.maskPath, plan.frames[i].frameNumber, plan.digits);
    }
    return job;
}

int runFrames(const RenderJob& base, const FramePlan& plan, bool resume, const FrameRenderer& render) {
    if (!plan.animated) {
        const RenderJob job = frameJob(base, plan, 0);
        if (resume && job.outputToFile && fileExists(job.outputPath)) {
            if (!job.quiet) std::fprintf(stderr, "rays: %s exists; skipped (resume)\n", printableMessage(job.outputPath).c_str());
            return 0;
        }
        return render(job);
    }
    InterruptScope interruptScope;  // a signal between two frames is seen before the next one starts
    size_t written = 0;
    for (size_t i = 0; i < plan.frames.size(); ++i) {
        RenderJob job = frameJob(base, plan, i);
        job.summary = false;
        const std::string label = frameLabel(plan, i);
        if (resume && job.outputToFile && fileExists(job.outputPath)) {
            if (!job.quiet) std::fprintf(stderr, "rays: %s: %s exists; skipped (resume)\n", label.c_str(), printableMessage(job.outputPath).c_str());
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        try {
            throwIfInterrupted();
            const int status = render(job);
            if (status != 0) return status;
        } catch (const Interrupted& e) {
            std::fprintf(stderr,
                         "rays: interrupted at %s: %s not written; %zu frame%s written before it; "
                         "run again with --resume to go on\n",
                         label.c_str(), printableMessage(job.outputPath).c_str(), written, written == 1 ? "" : "s");
            return e.exitStatus();
        }
        ++written;
        if (!job.quiet) {
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (job.outputToFile)
                std::fprintf(stderr, "rays: %s: wrote %s in %.2f s\n", label.c_str(), printableMessage(job.outputPath).c_str(), seconds);
            else
                std::fprintf(stderr, "rays: %s: rendered in %.2f s, no image written (Output_to_File=off)\n", label.c_str(), seconds);
        }
    }
    return 0;
}

}  // namespace rays::cli
