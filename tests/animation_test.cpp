// POV-Ray's animation arithmetic (apps/rays/frame_plan.cpp) and the frame loop
// (apps/rays/animation.cpp), in-process. The expected clocks, frame numbers and file names are
// those the installed povray 3.7 printed with #debug for the same options (docs/cli.md
// "Animation" lists the few places Rays differs). The loop is driven with a stand-in renderer that
// records each frame's job (its LanguageOptions clock and output path) and writes the file.
//
// rays_tests links rays_core only (the app's sources are not a library), so these sources are
// compiled into this test directly.
#include "../apps/rays/animation.cpp"
#include "../apps/rays/frame_plan.cpp"
#include "../apps/rays/interrupt.cpp"
#include "../apps/rays/paths.cpp"  // frame_plan and pov_options (pov_options_test) use it

#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rays/error.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::Error;
using rays::cli::AnimationOptions;
using rays::cli::FramePlan;
using rays::cli::frameFileName;
using rays::cli::planFrames;
using rays::cli::RenderJob;
using rays::test::readFile;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

AnimationOptions frames(int initial, int final) {
    AnimationOptions a;
    a.initialFrame = initial;
    a.finalFrame = final;
    return a;
}

std::vector<int> numbers(const FramePlan& p) {
    std::vector<int> n;
    for (const auto& f : p.frames) n.push_back(f.frameNumber);
    return n;
}

std::vector<double> clocks(const FramePlan& p) {
    std::vector<double> c;
    for (const auto& f : p.frames) c.push_back(f.clock);
    return c;
}

void expectClocks(const FramePlan& p, const std::vector<double>& expected) {
    const std::vector<double> got = clocks(p);
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-12) << "frame " << i;
}

std::string errorOf(const AnimationOptions& a) {
    try {
        planFrames(a);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// ---- the frame plan ----------------------------------------------------------------------------

TEST(FramePlan, AStillHasPovRaysStillIdentifiers) {
    const FramePlan p = planFrames(AnimationOptions{});
    ASSERT_EQ(p.frames.size(), 1u);
    EXPECT_FALSE(p.animated);
    const rays::sdl::AnimationClock& c = p.frames[0];
    EXPECT_EQ(c.frameNumber, 0);
    EXPECT_EQ(c.initialFrame, 0);
    EXPECT_EQ(c.finalFrame, 0);
    EXPECT_EQ(c.clock, 0);
    EXPECT_EQ(c.clockDelta, 0);
    EXPECT_EQ(c.initialClock, 0);
    EXPECT_EQ(c.finalClock, 0);
    EXPECT_FALSE(c.clockOn);
}

TEST(FramePlan, AStillWithAClockTurnsClockOn) {
    AnimationOptions a;
    a.clockGiven = true;
    a.clock = 0.7;
    const FramePlan p = planFrames(a);
    EXPECT_DOUBLE_EQ(p.frames[0].clock, 0.7);
    EXPECT_TRUE(p.frames[0].clockOn);
    a.clock = 0;  // +K0 too (povray: clock_on 1)
    EXPECT_TRUE(planFrames(a).frames[0].clockOn);
}

TEST(FramePlan, FinalFrameZeroIsAStill) {
    EXPECT_FALSE(planFrames(frames(1, 0)).animated);
    EXPECT_FALSE(planFrames(frames(1, -1)).animated);
}

TEST(FramePlan, ThreeFramesRunTheClockFromZeroToOne) {
    const FramePlan p = planFrames(frames(1, 3));
    EXPECT_TRUE(p.animated);
    EXPECT_EQ(p.digits, 1);
    EXPECT_EQ(numbers(p), (std::vector<int>{1, 2, 3}));
    expectClocks(p, {0, 0.5, 1});
    for (const auto& f : p.frames) {
        EXPECT_DOUBLE_EQ(f.clockDelta, 0.5);
        EXPECT_EQ(f.initialFrame, 1);
        EXPECT_EQ(f.finalFrame, 3);
        EXPECT_EQ(f.initialClock, 0);
        EXPECT_EQ(f.finalClock, 1);
        EXPECT_TRUE(f.clockOn);
    }
}

TEST(FramePlan, TenFramesHaveTwoDigits) {
    const FramePlan p = planFrames(frames(1, 10));
    EXPECT_EQ(p.digits, 2);
    EXPECT_EQ(p.frames.size(), 10u);
    EXPECT_NEAR(p.frames[1].clock, 1.0 / 9, 1e-12);
    EXPECT_NEAR(p.frames[0].clockDelta, 1.0 / 9, 1e-12);
    EXPECT_EQ(planFrames(frames(1, 100)).digits, 3);
}

TEST(FramePlan, InitialFrameZeroGivesElevenFrames) {
    const FramePlan p = planFrames(frames(0, 10));
    EXPECT_EQ(p.frames.size(), 11u);
    EXPECT_EQ(p.frames.front().frameNumber, 0);
    EXPECT_NEAR(p.frames[2].clock, 0.2, 1e-12);
    EXPECT_NEAR(p.frames[0].clockDelta, 0.1, 1e-12);
}

TEST(FramePlan, InitialAndFinalClock) {
    AnimationOptions a = frames(2, 5);
    a.initialClock = 1;
    a.finalClock = 3;
    const FramePlan p = planFrames(a);
    EXPECT_EQ(numbers(p), (std::vector<int>{2, 3, 4, 5}));
    expectClocks(p, {1, 1 + 2.0 / 3, 1 + 4.0 / 3, 3});
    EXPECT_NEAR(p.frames[0].clockDelta, 2.0 / 3, 1e-12);
    a = frames(1, 3);
    a.initialClock = 2;
    a.finalClock = 1;  // a clock running backwards
    expectClocks(planFrames(a), {2, 1.5, 1});
    EXPECT_DOUBLE_EQ(planFrames(a).frames[0].clockDelta, -0.5);
}

TEST(FramePlan, CyclicAnimationStopsOneStepShortOfTheFinalClock) {
    AnimationOptions a = frames(1, 3);
    a.cyclic = true;
    FramePlan p = planFrames(a);
    EXPECT_EQ(numbers(p), (std::vector<int>{1, 2, 3}));
    expectClocks(p, {0, 1.0 / 3, 2.0 / 3});
    EXPECT_EQ(p.frames[0].finalFrame, 4);  // povray reports the extra frame
    EXPECT_NEAR(p.frames[0].clockDelta, 1.0 / 3, 1e-12);
    a.finalClock = 2;
    expectClocks(planFrames(a), {0, 2.0 / 3, 4.0 / 3});
    a = frames(1, 9);
    a.cyclic = true;
    p = planFrames(a);
    EXPECT_EQ(p.digits, 2);  // final_frame is 10: out01 .. out09, as povray names them
    EXPECT_EQ(p.frames.size(), 9u);
}

TEST(FramePlan, SubsetsByFrameNumber) {
    AnimationOptions a = frames(1, 10);
    a.subsetStart = {true, 3};
    a.subsetEnd = {true, 5};
    const FramePlan p = planFrames(a);
    EXPECT_EQ(numbers(p), (std::vector<int>{3, 4, 5}));
    expectClocks(p, {2.0 / 9, 3.0 / 9, 4.0 / 9});  // the clock of the whole animation
    EXPECT_EQ(p.digits, 2);
    a.subsetStart = {true, 8};
    a.subsetEnd = {true, 20};
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{8, 9, 10}));  // Rays stops at Final_Frame
}

TEST(FramePlan, SubsetsByFraction) {
    AnimationOptions a = frames(1, 10);
    a.subsetStart = {true, 0.25};
    a.subsetEnd = {true, 0.55};
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{2, 3, 4, 5}));
    a.subsetStart = {true, 0.3};
    a.subsetEnd = {true, 0.5};
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{3, 4, 5}));
    a.subsetStart = {true, 0.05};
    a.subsetEnd = {true, 0.15};
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{1}));
    a = frames(0, 10);
    a.subsetStart = {true, 0.25};
    a.subsetEnd = {true, 0.35};
    // The ⌊f·n⌋-th of the n = 11 frames 0..10: frames 1 and 2. povray 3.7 takes frame numbers 2 and 3
    // (⌊f·n⌋ itself, the same as Rays only for Initial_Frame=1).
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{1, 2}));
    a = frames(1, 9);
    a.cyclic = true;
    a.subsetStart = {true, 0.5};
    a.subsetEnd = {true, 0.7};
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{5, 6, 7}));  // fractions of the 10 cyclic frames
}

TEST(FramePlan, FrameStep) {
    AnimationOptions a = frames(1, 10);
    a.frameStep = 3;
    EXPECT_EQ(numbers(planFrames(a)), (std::vector<int>{1, 4, 7, 10}));
    a.subsetStart = {true, 2};
    a.subsetEnd = {true, 9};
    const FramePlan p = planFrames(a);
    EXPECT_EQ(numbers(p), (std::vector<int>{2, 5, 8}));
    EXPECT_NEAR(p.frames[0].clockDelta, 1.0 / 9, 1e-12);  // clock_delta is still one frame's
}

TEST(FramePlan, OneFrameAnimationsAndBackwardFrames) {
    // +KFI1 +KFF1 is a still for POV-Ray 3.7 (frame_number 0, clock_on 0, no number in the name).
    FramePlan p = planFrames(frames(1, 1));
    EXPECT_FALSE(p.animated);
    EXPECT_EQ(numbers(p), std::vector<int>{0});
    EXPECT_FALSE(p.frames[0].clockOn);
    // +KFI3 +KFF3 is an animation of frame 3.
    p = planFrames(frames(3, 3));
    EXPECT_TRUE(p.animated);
    EXPECT_EQ(numbers(p), std::vector<int>{3});
    EXPECT_EQ(p.frames[0].clock, 0);  // povray: nan
    EXPECT_EQ(p.frames[0].clockDelta, 0);  // povray: inf
    p = planFrames(frames(5, 3));  // a final frame before the initial one is the initial one
    EXPECT_EQ(numbers(p), std::vector<int>{5});
    EXPECT_EQ(p.frames[0].finalFrame, 5);
}

TEST(FramePlan, SubsetsThatSelectNoFrameAreErrors) {
    AnimationOptions a = frames(1, 10);
    a.subsetStart = {true, 15};
    EXPECT_EQ(errorOf(a), "rays: error: Subset_Start_Frame selects frame 15, after the final frame 10");
    a.subsetStart = {true, 5};
    a.subsetEnd = {true, 3};
    EXPECT_EQ(errorOf(a), "rays: error: Subset_End_Frame selects frame 3, before the subset's first frame 5: no frame to render");
}

TEST(FramePlan, FileNamesCarryTheZeroPaddedFrameNumber) {
    EXPECT_EQ(frameFileName("out.png", 7, 2), "out07.png");
    EXPECT_EQ(frameFileName("out.png", 30, 2), "out30.png");
    EXPECT_EQ(frameFileName("out.png", 1, 1), "out1.png");
    EXPECT_EQ(frameFileName("out.x.png", 2, 1), "out.x2.png");  // before the last extension
    EXPECT_EQ(frameFileName("out7.png", 1, 1), "out71.png");    // a name ending in a digit: appended, as povray
    EXPECT_EQ(frameFileName("a.d/out", 5, 3), "a.d/out005");    // no extension
    EXPECT_EQ(frameFileName("dir/.png", 2, 1), "dir/.png2");     // a hidden file's dot is no extension
}

// ---- the loop ----------------------------------------------------------------------------------

struct Recorder {
    std::vector<RenderJob> jobs;
    int interruptAt = -1;  ///< 0-based call that throws Interrupted (-1: none)
    int failAt = -1;       ///< 0-based call that returns 2
    int signalAfter = -1;  ///< 0-based call that raises SIGINT after writing its file (between two frames)

    rays::cli::FrameRenderer renderer() {
        return [this](const RenderJob& job) {
            const int call = int(jobs.size());
            jobs.push_back(job);
            if (call == interruptAt) throw rays::cli::Interrupted(SIGINT);
            if (call == failAt) return 2;
            {
                rays::cli::InterruptScope nested;  // as runRender holds one
                std::ofstream(job.outputPath) << "frame " << job.language.animation.frameNumber;
            }
            if (call == signalAfter) ::raise(SIGINT);
            return 0;
        };
    }
};

RenderJob baseJob(const fs::path& dir) {
    RenderJob job;
    job.outputPath = (dir / "out.png").string();
    job.quiet = true;
    return job;
}

TEST(AnimationLoop, EachFrameGetsItsClockAndNumberedFile) {
    TempDir dir;
    Recorder rec;
    const FramePlan plan = planFrames(frames(1, 3));
    EXPECT_EQ(rays::cli::runFrames(baseJob(dir.path()), plan, false, rec.renderer()), 0);
    ASSERT_EQ(rec.jobs.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        const RenderJob& job = rec.jobs[size_t(i)];
        EXPECT_EQ(job.outputPath, (dir.path() / ("out" + std::to_string(i + 1) + ".png")).string());
        EXPECT_EQ(job.language.animation.frameNumber, i + 1);
        EXPECT_DOUBLE_EQ(job.language.animation.clock, 0.5 * i);
        EXPECT_TRUE(job.language.animation.clockOn);
        EXPECT_FALSE(job.summary);  // the loop prints its own line
        EXPECT_EQ(readFile(job.outputPath), "frame " + std::to_string(i + 1));
    }
}

TEST(AnimationLoop, AStillKeepsItsNameAndStillClock) {
    TempDir dir;
    Recorder rec;
    EXPECT_EQ(rays::cli::runFrames(baseJob(dir.path()), planFrames(AnimationOptions{}), false, rec.renderer()), 0);
    ASSERT_EQ(rec.jobs.size(), 1u);
    EXPECT_EQ(rec.jobs[0].outputPath, (dir.path() / "out.png").string());
    EXPECT_FALSE(rec.jobs[0].language.animation.clockOn);
    EXPECT_TRUE(rec.jobs[0].summary);
}

TEST(AnimationLoop, WrittenFramesAreRenderedAgainUnlessResuming) {
    TempDir dir;
    const FramePlan plan = planFrames(frames(1, 3));
    std::ofstream(dir.path() / "out2.png") << "old";
    Recorder again;
    rays::cli::runFrames(baseJob(dir.path()), plan, false, again.renderer());
    EXPECT_EQ(again.jobs.size(), 3u);
    EXPECT_EQ(readFile(dir.path() / "out2.png"), "frame 2");

    std::ofstream(dir.path() / "out2.png") << "old";
    fs::remove(dir.path() / "out3.png");
    Recorder resumed;
    rays::cli::runFrames(baseJob(dir.path()), plan, true, resumed.renderer());
    ASSERT_EQ(resumed.jobs.size(), 1u);  // out1 and out2 exist
    EXPECT_EQ(resumed.jobs[0].language.animation.frameNumber, 3);
    EXPECT_EQ(readFile(dir.path() / "out2.png"), "old");

    std::ofstream(dir.path() / "out.png") << "still";
    Recorder still;
    rays::cli::runFrames(baseJob(dir.path()), planFrames(AnimationOptions{}), true, still.renderer());
    EXPECT_TRUE(still.jobs.empty());  // a still that exists is skipped too
}

TEST(AnimationLoop, CtrlCStopsAtTheCurrentFrame) {
    TempDir dir;
    Recorder rec;
    rec.interruptAt = 1;
    RenderJob base = baseJob(dir.path());
    base.quiet = false;
    testing::internal::CaptureStderr();
    const int status = rays::cli::runFrames(base, planFrames(frames(1, 3)), false, rec.renderer());
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(status, 130);
    EXPECT_EQ(rec.jobs.size(), 2u);  // frame 3 never started
    EXPECT_TRUE(fs::exists(dir.path() / "out1.png"));
    EXPECT_FALSE(fs::exists(dir.path() / "out2.png"));
    EXPECT_NE(err.find("rays: frame 1 of 3 (frame_number 1, clock 0): wrote"), std::string::npos) << err;
    EXPECT_NE(err.find("rays: interrupted at frame 2 of 3 (frame_number 2, clock 0.5): " + (dir.path() / "out2.png").string() +
                       " not written; 1 frame written before it; run again with --resume to go on"),
              std::string::npos)
        << err;
}

TEST(AnimationLoop, ACtrlCBetweenTwoFramesStopsBeforeTheNext) {
    TempDir dir;
    Recorder rec;
    rec.signalAfter = 0;
    testing::internal::CaptureStderr();
    const int status = rays::cli::runFrames(baseJob(dir.path()), planFrames(frames(1, 3)), false, rec.renderer());
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(status, 130);
    EXPECT_EQ(rec.jobs.size(), 1u);
    EXPECT_TRUE(fs::exists(dir.path() / "out1.png"));
    EXPECT_FALSE(fs::exists(dir.path() / "out2.png"));
    EXPECT_NE(err.find("interrupted at frame 2 of 3"), std::string::npos) << err;
}

TEST(AnimationLoop, ANestedInterruptScopeKeepsASignalTheLoopsScopeCaught) {
    rays::cli::InterruptScope loop;
    ::raise(SIGINT);  // between two frames
    EXPECT_TRUE(rays::cli::interrupted());
    {
        rays::cli::InterruptScope frame;  // the next frame's runRender
        EXPECT_TRUE(rays::cli::interrupted());
    }
    EXPECT_TRUE(rays::cli::interrupted());
    EXPECT_THROW(rays::cli::throwIfInterrupted(), rays::cli::Interrupted);
}

TEST(AnimationLoop, ACtrlCOnAStillIsRethrown) {
    TempDir dir;
    Recorder rec;
    rec.interruptAt = 0;
    EXPECT_THROW(rays::cli::runFrames(baseJob(dir.path()), planFrames(AnimationOptions{}), false, rec.renderer()),
                 rays::cli::Interrupted);
}

TEST(AnimationLoop, AFailedFrameStopsTheLoop) {
    TempDir dir;
    Recorder rec;
    rec.failAt = 1;
    EXPECT_EQ(rays::cli::runFrames(baseJob(dir.path()), planFrames(frames(1, 3)), false, rec.renderer()), 2);
    EXPECT_EQ(rec.jobs.size(), 2u);
}

}}  // namespace RAYS_TEST_UNIT, namespace
