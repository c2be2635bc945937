#include "frame_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "paths.h"
#include "rays/error.h"

namespace rays::cli {
namespace {

int decimalDigits(int n) {
    int d = 1;
    for (; n >= 10; n /= 10) ++d;
    return d;
}

// A still (POV-Ray 3.7, observed): frame_number, initial/final frame and clock all 0; clock is the
// Clock option (0 without it) and clock_on says whether Clock was given.
FramePlan stillPlan(const AnimationOptions& a) {
    sdl::AnimationClock c;
    c.clock = a.clockGiven ? a.clock : 0.0;
    c.clockDelta = 0;
    c.frameNumber = 0;
    c.initialFrame = c.finalFrame = 0;
    c.initialClock = c.finalClock = 0;
    c.clockOn = a.clockGiven;
    FramePlan p;
    p.frames.push_back(c);
    return p;
}

// A subset bound as a frame number. A fraction f (below 1) of an animation of `count` frames is
// frame initial − 1 + ⌊f·count⌋: POV-Ray 3.7 computes ⌊f·count⌋ alone, which is the same for the
// usual Initial_Frame=1 (and ignores Initial_Frame otherwise); a value from 1 on is a frame number.
int subsetFrame(const PovBound& b, int initial, int count) {
    if (b.value < 1) return initial - 1 + int(std::floor(b.value * count));
    return int(b.value);
}

}  // namespace

FramePlan planFrames(const AnimationOptions& a) {
    // POV-Ray: Final_Frame 0 (or unset, -1) is a still, and so is Initial_Frame=Final_Frame=1 (frame
    // 0, clock_on 0, output not numbered; measured: +KFI3 +KFF3 is an animation of frame 3).
    if (a.finalFrame < 1 || (a.finalFrame == 1 && a.initialFrame == 1 && !a.cyclic)) return stillPlan(a);
    if (a.finalFrame > kMaxFrameNumber || a.initialFrame > kMaxFrameNumber)
        throw Error("rays: error: frame numbers go up to " + std::to_string(kMaxFrameNumber) + ", got " +
                    std::to_string(std::max(a.finalFrame, a.initialFrame)));
    const int initial = a.initialFrame;
    const int last = std::max(a.finalFrame, initial);  // a final frame before the initial one is the initial one
    // Cyclic_Animation: the clock runs as if there were one more frame, so the last frame rendered
    // is one step short of final_clock; final_frame reports that extra frame (POV-Ray 3.7).
    const int finalFrame = a.cyclic ? last + 1 : last;
    const int span = finalFrame - initial;
    const int count = span + 1;
    // POV-Ray divides by zero for a one-frame animation (clock nan, clock_delta inf); Rays gives that
    // frame initial_clock and a clock_delta of 0.
    const double delta = span > 0 ? (a.finalClock - a.initialClock) / span : 0.0;

    int first = a.subsetStart.given ? subsetFrame(a.subsetStart, initial, count) : initial;
    int end = a.subsetEnd.given ? subsetFrame(a.subsetEnd, initial, count) : last;
    first = std::max(first, initial);
    end = std::min(end, last);  // POV-Ray would go on past Final_Frame; Rays stops there
    if (first > last)
        throw Error("rays: error: Subset_Start_Frame selects frame " + std::to_string(first) +
                    ", after the final frame " + std::to_string(last));
    if (end < first)
        throw Error("rays: error: Subset_End_Frame selects frame " + std::to_string(end) +
                    ", before the subset's first frame " + std::to_string(first) + ": no frame to render");

    const int step = std::max(1, a.frameStep);
    const int64_t frames = (int64_t(end) - first) / step + 1;
    if (frames > kMaxFramesPerRun)
        throw Error("rays: error: the animation has " + std::to_string(frames) + " frames to render, more than the limit of " +
                    std::to_string(kMaxFramesPerRun) + " per run (render it in parts with Subset_Start_Frame and Subset_End_Frame, +SF +EF)");
    FramePlan p;
    p.animated = true;
    p.digits = decimalDigits(finalFrame);
    for (int64_t f = first; f <= end; f += step) {
        sdl::AnimationClock c;
        c.frameNumber = int(f);
        c.clock = span > 0 ? a.initialClock + (a.finalClock - a.initialClock) * double(f - initial) / span : a.initialClock;
        c.clockDelta = delta;
        c.initialFrame = initial;
        c.finalFrame = finalFrame;
        c.initialClock = a.initialClock;
        c.finalClock = a.finalClock;
        c.clockOn = true;
        p.frames.push_back(c);
    }
    return p;
}

std::string frameFileName(const std::string& output, int frame, int digits) {
    size_t dot = extensionDot(output);
    if (dot == std::string::npos) dot = output.size();  // no extension: the number goes at the end
    char number[32];
    std::snprintf(number, sizeof number, "%0*d", digits, frame);
    return output.substr(0, dot) + number + output.substr(dot);
}

}  // namespace rays::cli
