// An animation spread over the MPI ranks a whole frame at a time: rank 0 hands out the frames
// still to render on request (the ranks that finish sooner ask again sooner), each rank parses
// and renders its frame with its own threads and writes it itself, atomically, as a one-process
// run writes it (so frames are byte-identical to a one-process animation's). Rank 0 renders frames
// too, on a thread of its own, while its main thread answers the others. With --resume rank 0
// alone decides which frames exist already (the rule of runFrames) and hands out only the others.
// Compiled only with RAYS_MPI.
#pragma once
#include "../animation.h"

namespace rays::cli::mpi {

/// Renders the frames of plan (an animation) on all ranks; every rank calls it with the same
/// arguments. Rank 0 prints a line per frame written (naming the rank), a progress bar over the
/// frames on a terminal, and the MPI summary line. Returns 0, the first non-zero status of rank
/// 0's own frames, or 128 + the signal after Ctrl-C; an error on any rank throws (and main's
/// mpi::finish stops every rank).
int runFramesOnRanks(const RenderJob& base, const FramePlan& plan, bool resume, const FrameRenderer& render);

}  // namespace rays::cli::mpi
