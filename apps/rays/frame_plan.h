// POV-Ray's animation arithmetic (reference 3.2.1 "Animation Options", checked against the
// installed povray 3.7 binary): which frames an animation renders, each frame's clock identifiers
// (sdl::AnimationClock) and the numbered output file names. Pure functions of plain values.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rays/sdl/options.h"

namespace rays::cli {

/// A bound as POV-Ray writes it: below 1 a fraction, from 1 on a 1-based number. A subset frame
/// (Subset_Start_Frame, +SF: of the animation, a frame number) or a row or column (Start_Row, +SR,
/// …: of the image, a pixel number; pov_options.h).
struct PovBound {
    bool given = false;
    double value = 0;
};

/// The animation options as given (Initial_Frame … Frame_Step, Clock).
struct AnimationOptions {
    int initialFrame = 1;      ///< Initial_Frame, +KFI
    int finalFrame = -1;       ///< Final_Frame, +KFF; below 1: no animation loop (a still)
    double initialClock = 0;   ///< Initial_Clock, +KI
    double finalClock = 1;     ///< Final_Clock, +KF
    bool clockGiven = false;   ///< Clock, +K was given (a still's clock; clock_on becomes true)
    double clock = 0;          ///< Clock, +K
    bool cyclic = false;       ///< Cyclic_Animation, +KC
    PovBound subsetStart;    ///< Subset_Start_Frame, +SF
    PovBound subsetEnd;      ///< Subset_End_Frame, +EF
    int frameStep = 1;         ///< Frame_Step, +STP
};

/// The frames to render, in order.
struct FramePlan {
    std::vector<sdl::AnimationClock> frames;  ///< one entry for a still
    bool animated = false;  ///< numbered output files (the animation loop)
    int digits = 0;         ///< digits of the frame number in file names (those of final_frame)
};

/// Frame numbers (Initial_Frame, Final_Frame) are at most this: 9 digits in file names.
inline constexpr int kMaxFrameNumber = 999999999;
/// Frames one run renders at most (each frame's clock is planned up front).
inline constexpr int64_t kMaxFramesPerRun = 1000000;

/// The frames POV-Ray 3.7 renders for these options; throws Error ("rays: error: ...") for a subset
/// that selects no frame.
FramePlan planFrames(const AnimationOptions& a);

/// The output file of frame `frame`: the number, zero-padded to `digits`, goes before the extension
/// ("out.png", 7, 2 → "out07.png"; "out.x.png" → "out.x07.png"; "dir/out" → "dir/out07").
std::string frameFileName(const std::string& output, int frame, int digits);

}  // namespace rays::cli
