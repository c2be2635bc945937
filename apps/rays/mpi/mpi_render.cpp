#include "mpi_render.h"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

#include "../interrupt.h"
#include "mpi_lost_rank.h"
#include "mpi_session.h"
#include "mpi_summary.h"
#include "mpi_wait.h"

namespace rays::cli::mpi {
namespace {

using Clock = std::chrono::steady_clock;

// Messages: a worker's report (tag kReport) is an int64 band index (-1: nothing yet) followed by
// that band's pixels (Vec3, row-major); rank 0 answers each report with the next band (kAssign,
// one int, -1: no more work).
constexpr int kReport = 1, kAssign = 2;
constexpr size_t kHeader = sizeof(int64_t);

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Image rows [y0, y1) of band b.
int bandY0(int b) { return b * TileRenderer::kTileSize; }
int bandY1(int b, int height) { return std::min(height, bandY0(b) + TileRenderer::kTileSize); }

// Renders band b into img (whose row 0 is image row imgY0) with all the rank's threads.
void renderBand(TileRenderer& tiles, const RenderSettings& s, int b, ImageF& img, int imgY0) {
    const int tx = tiles.tilesX();
    parallelFor(tx, s.threads, [&](int i, int w) { tiles.renderTile(b * tx + i, w, img, imgY0); });
}

// A worker rank: asks for bands, renders them, sends them back with the next request.
double serveAsWorker(TileRenderer& tiles, const RenderSettings& s) {
    ImageF band(s.width, TileRenderer::kTileSize);
    std::vector<char> msg(kHeader);
    int64_t done = -1;
    std::memcpy(msg.data(), &done, kHeader);
    double busy = 0;
    dieIfTestAsks();
    for (;;) {
        sendGently(msg.data(), int(msg.size()), MPI_BYTE, 0, kReport);
        int b = -1;
        recvGently(&b, 1, MPI_INT, 0, kAssign);
        if (b < 0) return busy;
        const auto t0 = Clock::now();
        renderBand(tiles, s, b, band, bandY0(b));
        busy += secondsSince(t0);
        throwIfInterrupted();  // a band cut short by a signal is not sent
        const size_t bytes = size_t(bandY1(b, s.height) - bandY0(b)) * size_t(s.width) * sizeof(Vec3);
        msg.resize(kHeader + bytes);
        done = b;
        std::memcpy(msg.data(), &done, kHeader);
        std::memcpy(msg.data() + kHeader, band.pixels.data(), bytes);
    }
}

// Rank 0: renders bands on a thread of its own while the main thread (the only one calling MPI)
// answers the workers' reports and copies their bands into the image (the time that takes is
// added to gather). After a signal it hands out nothing more and returns once its own thread
// stops; the caller then finds the run interrupted.
double serveAsRoot(TileRenderer& tiles, const RenderSettings& s, ImageF& img, const ProgressFn& progress,
                   const RowsFn& onRows, double& gather) {
    const int bands = tiles.tilesY();
    std::atomic<int> next{0}, finished{0};
    double busy = 0;
    std::thread local([&] {
        const auto t0 = Clock::now();
        for (int b = next.fetch_add(1); b < bands; b = next.fetch_add(1)) {
            renderBand(tiles, s, b, img, 0);
            if (onRows && !interrupted()) onRows(img, bandY0(b), bandY1(b, s.height), 0);
            finished.fetch_add(1);
        }
        busy = secondsSince(t0);
    });
    int active = size() - 1;
    std::vector<char> msg;
    auto lastProgress = Clock::now();
    dieIfTestAsks();
    while (active > 0 && !interrupted()) {
        int ready = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, kReport, MPI_COMM_WORLD, &ready, &st);
        if (progress && secondsSince(lastProgress) > 0.1) {
            progress(double(finished.load()) / bands);
            lastProgress = Clock::now();
        }
        if (!ready) {
            // Poll gently: the render threads need the cores more than this loop does.
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            continue;
        }
        const auto received = Clock::now();
        int bytes = 0;
        MPI_Get_count(&st, MPI_BYTE, &bytes);
        msg.resize(size_t(bytes));
        MPI_Recv(msg.data(), bytes, MPI_BYTE, st.MPI_SOURCE, kReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        int64_t b = -1;
        std::memcpy(&b, msg.data(), kHeader);
        if (b >= 0) {
            std::memcpy(&img.at(0, bandY0(int(b))), msg.data() + kHeader, size_t(bytes) - kHeader);
            finished.fetch_add(1);
        }
        gather += secondsSince(received);
        int assign = next.fetch_add(1);
        if (assign >= bands) {
            assign = -1;
            --active;
        }
        MPI_Send(&assign, 1, MPI_INT, st.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
        // Compressing the band (a plain PNG) comes after the answer: the rank renders meanwhile.
        if (b >= 0 && onRows) onRows(img, bandY0(int(b)), bandY1(int(b), s.height), 0);
    }
    // The last bands may still be rendering here; progress goes on until they are done.
    if (interrupted()) next.store(bands);  // the local thread takes no further band
    while (finished.load() < bands && !interrupted()) {
        if (progress) progress(double(finished.load()) / bands);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    local.join();
    if (progress) progress(1.0);
    return busy;
}

}  // namespace

ImageF renderDistributed(const Scene& scene, const Bvh& bvh, const RenderSettings& s, double parseBuildSeconds,
                         TraceStats& stats, const ProgressFn& progress, const RowsFn& onRows, ShareFigures& share) {
    TileRenderer tiles(scene, bvh, s);
    ImageF img;
    RankFigures mine;
    mine.parseBuild = parseBuildSeconds;
    if (rank() == 0) {
        img = ImageF::uninitialized(s.width, s.height);
        mine.busy = serveAsRoot(tiles, s, img, progress, onRows, share.gatherSeconds);
    } else {
        mine.busy = serveAsWorker(tiles, s);
    }
    throwIfInterrupted();  // the ranks stop without the collectives below: finish() aborts the run
    // Counters, rays and busy times come together on rank 0 for the summary (the ranks done
    // first sleep until the last one is).
    barrierGently();
    const TraceStats counted = tiles.stats();
    uint64_t counts[3] = {counted.primaryRays, counted.secondaryRays, counted.shadowRays}, sums[3] = {0, 0, 0};
    MPI_Reduce(counts, sums, 3, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    mine.render = mine.busy;
    mine.rays = double(counted.total());
    share.ranks = gatherFigures(mine);
    if (rank() != 0) return ImageF{};
    stats.add(TraceStats{sums[0], sums[1], sums[2]});
    return img;
}

}  // namespace rays::cli::mpi
