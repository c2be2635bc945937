// The frame loop (POV-Ray reference 3.2.1.2 and 3.2.6.2): one render per frame of a FramePlan, the
// scene parsed again for each with that frame's clock, numbered output files, one progress line
// per frame, frames already written skipped only with --resume (or +C), and Ctrl-C stopping at the
// frame being rendered (that frame is not written; the frames before it stay).
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include "frame_plan.h"
#include "render_command.h"

namespace rays::cli {

/// Renders one job and returns its exit status (runRender in the program, a stand-in in tests);
/// throws Interrupted after Ctrl-C.
using FrameRenderer = std::function<int(const RenderJob&)>;

/// Frame i of plan for messages: "frame 2 of 3 (frame_number 2, clock 0.5)".
std::string frameLabel(const FramePlan& plan, size_t i);

/// The job of frame i of plan: base with the frame's clock in language.animation and, for an
/// animation, the numbered output file and edge mask (frameFileName).
RenderJob frameJob(const RenderJob& base, const FramePlan& plan, size_t i);

/// Renders every frame of plan in order with render; returns 0, or the first non-zero status.
/// With resume, a frame whose output file exists is skipped. For an animation, a Ctrl-C ends the
/// loop with a message naming the frame and returns 130 (143 for SIGTERM); for a still it throws
/// Interrupted as runRender does.
int runFrames(const RenderJob& base, const FramePlan& plan, bool resume, const FrameRenderer& render);

}  // namespace rays::cli
