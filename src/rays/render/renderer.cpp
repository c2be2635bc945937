#include "rays/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <cmath>
#include <thread>

#include "rays/render/sampler.h"

namespace rays {
namespace {

constexpr int kTile = 16;

}  // namespace

int resolveThreads(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(hw);
}

Vec3 renderPixel(const Tracer& tracer, const Camera& camera, const RenderSettings& s, int i, int j,
                 TraceContext& ctx) {
    if (s.spp > 0) {
        // Jittered sampling: stratified on a k×k grid when spp is a perfect square.
        const int k = int(std::lround(std::sqrt(double(s.spp))));
        const bool strata = k * k == s.spp;
        Vec3 sum;
        for (int n = 0; n < s.spp; ++n) {
            SampleRng rng(uint32_t(i), uint32_t(j), uint32_t(n), s.seed);
            double dx = rng.next(), dy = rng.next();
            if (s.spp == 1) dx = dy = 0.5;
            if (strata) {
                dx = (n % k + dx) / k;
                dy = (n / k + dy) / k;
            }
            sum += tracer.tracePrimary(camera.rayThrough(i + dx, j + dy, s.width, s.height), ctx);
        }
        return sum / double(s.spp);
    }
    const int g = std::max(1, s.gridSamples);
    Vec3 sum;
    for (int sy = 0; sy < g; ++sy)
        for (int sx = 0; sx < g; ++sx)
            sum += tracer.tracePrimary(
                camera.rayThrough(i + (sx + 0.5) / g, j + (sy + 0.5) / g, s.width, s.height), ctx);
    return sum / double(g * g);
}

ImageF render(const Scene& scene, const Bvh& bvh, const RenderSettings& s, TraceStats& stats,
              const ProgressFn& progress) {
    ImageF img(s.width, s.height);
    const Camera& camera = scene.cameras.at(size_t(s.cameraIndex));
    const Tracer tracer(scene, bvh, s);
    const int tilesX = (s.width + kTile - 1) / kTile, tilesY = (s.height + kTile - 1) / kTile;
    const int tileCount = tilesX * tilesY;
    const int nThreads = std::min(resolveThreads(s.threads), std::max(1, tileCount));
    std::atomic<int> nextTile{0}, doneTiles{0};
    std::mutex doneMutex;
    std::condition_variable doneCv;
    std::vector<TraceContext> perThread(static_cast<size_t>(nThreads));

    auto worker = [&](int w) {
        TraceContext& st = perThread[size_t(w)];
        for (int t = nextTile.fetch_add(1); t < tileCount; t = nextTile.fetch_add(1)) {
            const int x0 = (t % tilesX) * kTile, y0 = (t / tilesX) * kTile;
            const int x1 = std::min(x0 + kTile, s.width), y1 = std::min(y0 + kTile, s.height);
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x)
                    img.at(x, y) = renderPixel(tracer, camera, s, x, s.height - 1 - y, st);
            if (doneTiles.fetch_add(1) + 1 == tileCount) {
                std::lock_guard<std::mutex> lock(doneMutex);
                doneCv.notify_all();
            }
        }
    };

    std::vector<std::thread> pool;
    for (int w = 1; w < nThreads; ++w) pool.emplace_back(worker, w);
    if (progress) {
        // The calling thread reports progress while the pool works, then joins in.
        std::thread last(worker, 0);
        std::unique_lock<std::mutex> lock(doneMutex);
        while (doneTiles.load() < tileCount) {
            progress(double(doneTiles.load()) / tileCount);
            doneCv.wait_for(lock, std::chrono::milliseconds(100));
        }
        lock.unlock();
        last.join();
        progress(1.0);
    } else {
        worker(0);
    }
    for (std::thread& th : pool) th.join();
    for (const TraceContext& st : perThread) stats.add(st.stats);
    return img;
}

}  // namespace rays
