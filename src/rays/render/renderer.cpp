#include "rays/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <numeric>
#include <thread>

#include "rays/math/sampling.h"
#include "rays/render/aov.h"
#include "rays/render/pov_output.h"
#include "rays/render/photon_shooting.h"
#include "rays/render/radiosity_pretrace.h"
#include "rays/render/sampler.h"
#include "rays/util/worker_pool.h"

namespace rays {
namespace {

constexpr int kTile = TileRenderer::kTileSize;

// A traced colour as the image holds it: course scenes as traced; POV-Ray scenes as POV-Ray writes
// them, sRGB(c^assumed_gamma) or with File_Gamma, or linear light for HDR files (linear, docs/aov.md).
Vec3 pixelOutput(Vec3 c, bool povScene, bool linear, double assumedGamma, double fileGamma) {
    if (!povScene) return c;
    return linear ? povLinearColor(c, assumedGamma) : povOutputColor(c, assumedGamma, fileGamma);
}

// A linear colour as POV-Ray 3.7's anti-aliasing compares it: clamped to [0, 1] and raised to
// 1/gamma (Antialias_Gamma; POV-Ray's change log for 3.7: the comparison uses gamma-adjusted
// copies of the samples, the averaging the linear ones).
Vec3 aaLook(Vec3 linear, double gamma) {
    Vec3 r;
    for (int k = 0; k < 3; ++k) r[k] = std::pow(std::clamp(linear[k], 0.0, 1.0), 1 / gamma);
    return r;
}

// POV-Ray's method 1 (reference 3.2.8.7): a pixel whose colour differs from its left or upper
// neighbour's by more than the threshold (|Δr| + |Δg| + |Δb|) is supersampled, and so is that
// neighbour.
using Looks = std::vector<Vec3, PixelAllocator<Vec3>>;  // unset until the first pass writes them

std::vector<uint8_t> markColourChanges(const Looks& looks, int w, int h, double threshold) {
    std::vector<uint8_t> mark(looks.size(), 0);
    auto differ = [&](size_t a, size_t b) {
        const Vec3 d = looks[a] - looks[b];
        return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z) > threshold;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (x > 0 && differ(i, i - 1)) mark[i] = mark[i - 1] = 1;
            if (y > 0 && differ(i, i - size_t(w))) mark[i] = mark[i - size_t(w)] = 1;
        }
    return mark;
}

// Rays' edge-guided rule: pixels whose first sample saw other objects or shadows than any of its
// 8 neighbours'.
std::vector<uint8_t> markPathChanges(const std::vector<PathInfo>& seen, int w, int h) {
    std::vector<uint8_t> mark(seen.size(), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int dy = -1; dy <= 1 && !mark[size_t(y) * w + x]; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    if (!(seen[size_t(y) * w + x] == seen[size_t(ny) * w + nx])) {
                        mark[size_t(y) * w + x] = 1;
                        break;
                    }
                }
    return mark;
}

// Support radius (pixels, around the centre) and weight of the reconstruction filters.
double filterRadius(PixelFilter f) {
    switch (f) {
        case PixelFilter::Box: return 0.5;
        case PixelFilter::Tent: return 1.0;
        case PixelFilter::Gaussian: return 1.5;
    }
    return 0.5;
}

double filterWeight(PixelFilter f, double x, double y) {
    switch (f) {
        case PixelFilter::Box: return 1.0;
        case PixelFilter::Tent: return std::max(0.0, 1 - std::fabs(x)) * std::max(0.0, 1 - std::fabs(y));
        case PixelFilter::Gaussian: return std::exp(-(x * x + y * y) / (2 * 0.25));
    }
    return 1.0;
}

// Position of sample n of count in [0,1)² for the anti-aliasing mode.
void samplePoint(AaMode mode, int n, int count, SampleRng& rng, double& a, double& b) {
    if (count == 1 && mode == AaMode::Grid) {
        a = b = 0.5;
        return;
    }
    if (mode == AaMode::Random) {
        a = rng.next();
        b = rng.next();
        return;
    }
    const int k = std::max(1, int(std::lround(std::sqrt(double(count)))));
    const double ja = mode == AaMode::Grid ? 0.5 : rng.next();
    const double jb = mode == AaMode::Grid ? 0.5 : rng.next();
    a = (n % k + ja) / k;
    b = (n / k % k + jb) / k;
}

// Samples actually taken for spp: Grid and Stratified use the nearest square k×k.
int sampleCount(AaMode mode, int spp) {
    if (mode == AaMode::Random) return std::max(1, spp);
    const int k = std::max(1, int(std::lround(std::sqrt(double(spp)))));
    return k * k;
}

// A multiplier coprime to count, so that lens strata are visited in a different order than
// pixel strata (decorrelating the two 2-D sample sets).
int lensStride(int count) {
    for (int p : {7, 11, 13, 17, 19, 23, 29, 31})
        if (std::gcd(p, count) == 1) return p;
    return 1;
}

// The pixel strata's stride under adaptive focal blur: coprime to count and unlike the lens's.
int pixelStrideFor(int count, int lensStride) {
    for (int p : {5, 7, 11, 13, 17, 19, 23, 29, 31})
        if (p != lensStride && std::gcd(p, count) == 1) return p;
    return 1;
}

}  // namespace

int resolveThreads(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(hw);
}

namespace {
std::atomic<const std::atomic<bool>*> cancelFlag{nullptr};
bool cancelled() {
    const std::atomic<bool>* f = cancelFlag.load(std::memory_order_acquire);
    return f && f->load(std::memory_order_relaxed);
}
}  // namespace

void setCancelFlag(const std::atomic<bool>* flag) { cancelFlag.store(flag, std::memory_order_release); }

void parallelFor(int count, int threads, const std::function<void(int, int)>& body, const ProgressFn& progress) {
    const int n = std::min(resolveThreads(threads), std::max(1, count));
    std::atomic<int> next{0}, done{0};
    std::mutex m;
    std::condition_variable cv;
    const std::function<void(int)> worker = [&](int w) {
        for (int i = next.fetch_add(1); i < count && !cancelled(); i = next.fetch_add(1)) {
            body(i, w);
            if (done.fetch_add(1) + 1 == count) {
                std::lock_guard<std::mutex> lock(m);
                cv.notify_all();
            }
        }
    };
    // Workers run on the process's pool threads (worker_pool.h). With progress the calling thread
    // only reports it: all n work elsewhere.
    const int firstElsewhere = progress ? 0 : 1;
    runAlongside(firstElsewhere, n - firstElsewhere, worker, [&] {
        if (!progress) return worker(0);
        std::unique_lock<std::mutex> lock(m);
        while (done.load() < count && !cancelled()) {
            progress(double(done.load()) / std::max(1, count));
            cv.wait_for(lock, std::chrono::milliseconds(100));
        }
    });
    if (progress) progress(1.0);
}

ViewSetup resolveView(const Scene& scene, const RenderSettings& s) {
    ViewSetup v;
    v.camera = scene.cameras.at(size_t(s.cameraIndex));
    v.rays = CameraRays(v.camera);
    v.aperture = s.aperture >= 0 ? s.aperture : v.camera.aperture;
    if (v.camera.projection != Projection::Perspective) v.aperture = 0;  // focal blur: perspective only
    v.focalDistance = s.focalDistance > 0 ? s.focalDistance : v.camera.focalDistance();
    if (v.focalDistance <= 0) v.focalDistance = length(v.camera.lookAt - v.camera.location);
    v.samples = sampleCount(s.aa, s.spp);
    v.normals = &scene.normals;
    v.patterns = &scene.pigments;
    if (v.aperture > 0) {
        const int dof = s.dofSamples > 0 ? s.dofSamples : (v.camera.blurSamples > 0 ? v.camera.blurSamples : 16);
        v.samples = std::max(v.samples, sampleCount(s.aa == AaMode::Grid && s.spp == 1 ? AaMode::Stratified : s.aa, dof));
    }
    return v;
}

// POV-Ray's camera `normal` (reference 3.4.2.3, "Camera Ray Perturbation"), as measured with
// POV-Ray 3.7 (sine-wave gradient normals seen on a ramp-coloured wall): the pattern is evaluated
// at the sample's screen point (u, v, 0), u and v in [−½, ½] across the image (v up), whatever the
// camera's place, and the unit ray direction is tilted as a surface normal there (world axes).
Ray cameraRayAt(const ViewSetup& view, double px, double py, int w, int h) {
    Ray ray = view.rays.rayThrough(px, py, w, h);
    if (view.camera.normal < 0 || CameraRays::missed(ray)) return ray;
    const Vec3 screen{px / w - 0.5, py / h - 0.5, 0};
    ray.dir = view.normals->atRoot(*view.patterns, view.camera.normal, screen, normalize(ray.dir));
    return ray;
}

namespace {

// A mesh camera's pixel (scene/mesh_camera.h): each sample's rays from the faces the pixel maps
// to. A ray with no face is not shot and does not count in the average (POV-Ray 3.7's changelog,
// "Mesh Camera"); a pixel with none is black (measured).
Vec3 meshCameraPixel(const Tracer& tracer, const ViewSetup& view, const RenderSettings& s, int i, int j,
                     TraceContext& ctx, PathInfo* info) {
    const int count = view.samples, rays = view.rays.mesh->raysShot();
    const double radius = filterRadius(s.filter);
    if (info) *info = PathInfo{};
    bool first = true;
    Vec3 sum;
    double weightSum = 0;
    for (int n = 0; n < count; ++n) {
        ctx.rng = SampleRng(uint32_t(i), uint32_t(j), uint32_t(n), s.seed);
        double a, b;
        samplePoint(s.aa, n, count, ctx.rng, a, b);
        const double dx = (2 * a - 1) * radius, dy = (2 * b - 1) * radius;
        const double w = filterWeight(s.filter, dx, dy);
        for (int k = 0; k < rays; ++k) {
            const Ray ray = view.rays.meshRay(k, i + 0.5 + dx, j + 0.5 + dy, s.width, s.height);
            if (CameraRays::missed(ray)) continue;
            weightSum += w;
            sum += w * tracer.tracePrimary(ray, ctx, nullptr, first ? info : nullptr);
            first = false;
        }
    }
    return weightSum > 0 ? sum / weightSum : Vec3{};
}

}  // namespace

Vec3 renderPixel(const Tracer& tracer, const ViewSetup& view, const RenderSettings& s, int i, int j,
                 TraceContext& ctx, PathInfo* info) {
    if (view.rays.mesh) return meshCameraPixel(tracer, view, s, i, j, ctx, info);
    const int count = view.samples;
    // With depth of field and no explicit anti-aliasing, samples are stratified over the pixel.
    const AaMode mode = (view.aperture > 0 && s.aa == AaMode::Grid && s.spp == 1) ? AaMode::Stratified : s.aa;
    const double radius = filterRadius(s.filter);
    const int stride = lensStride(count);
    const Camera& cam = view.camera;
    // POV-Ray's adaptive focal blur (Camera::blurZ2): pixel strata are visited in a spread order
    // too, so that the samples taken before the stop cover the pixel.
    const bool adaptive = view.aperture > 0 && cam.blurZ2 > 0;
    const int pixelStride = adaptive ? pixelStrideFor(count, stride) : 1;
    const int minSamples = std::min(count, std::max(1, cam.blurMinSamples));
    Vec3 sum, mean, m2;
    double weightSum = 0;
    for (int n = 0; n < count; ++n) {
        ctx.rng = SampleRng(uint32_t(i), uint32_t(j), uint32_t(n), s.seed);
        double a, b;
        samplePoint(mode, int((int64_t(n) * pixelStride) % count), count, ctx.rng, a, b);
        // Map [0,1)² onto the filter support around the pixel centre.
        const double dx = (2 * a - 1) * radius, dy = (2 * b - 1) * radius;
        const double w = filterWeight(s.filter, dx, dy);
        Ray ray = cameraRayAt(view, i + 0.5 + dx, j + 0.5 + dy, s.width, s.height);
        if (view.aperture > 0) {
            // Thin lens: start on a disc of radius `aperture` around the eye (camera plane), aim
            // at the point where the pinhole ray meets the focal plane.
            const Vec3 fwd = view.rays.forward;
            const Vec3 focus = ray.at(view.focalDistance / dot(ray.dir, fwd));
            double la, lb;
            samplePoint(AaMode::Stratified, int((int64_t(n) * stride) % count), count, ctx.rng, la, lb);
            double lx, ly;
            concentricDisc(la, lb, lx, ly);
            const Vec3 ru = normalize(cam.right), uu = normalize(cam.up);
            const Vec3 origin = cam.location + view.aperture * (lx * ru + ly * uu);
            ray = Ray{origin, normalize(focus - origin)};
        }
        if (n == 0 && info) *info = PathInfo{};
        weightSum += w;
        const Vec3 c = CameraRays::missed(ray) ? Vec3{}  // outside the projection: black (as POV-Ray)
                                               : tracer.tracePrimary(ray, ctx, nullptr, n == 0 ? info : nullptr);
        sum += w * c;
        if (adaptive) {
            // Welford's running mean and sum of squared deviations, per channel.
            const Vec3 d = c - mean;
            mean += d / double(n + 1);
            m2 += d * (c - mean);
            const double limit = cam.blurVariance * double(n + 1) * double(n) / cam.blurZ2;  // z²·s²/(n+1) ≤ variance
            if (n + 1 >= minSamples && n > 0 && m2.x <= limit && m2.y <= limit && m2.z <= limit) break;
        }
    }
    return weightSum > 0 ? sum / weightSum : Vec3{};
}

TileRenderer::TileRenderer(const Scene& scene, const Bvh& bvh, const RenderSettings& s)
    : s_(s),
      view_(resolveView(scene, s)),
      // The same origins render() builds for a single-pass render (pinhole unless a lens spreads rays).
      origins_(Tracer::buildSharedOrigins(scene, bvh, view_.aperture <= 0 && !view_.rays.mesh ? &view_.rays.location : nullptr,
                                          double(s.width) * double(s.height) * double(view_.samples), s.threads)),
      tracer_(scene, bvh, s, &origins_),
      povOutput_(scene.pov.enabled),
      assumedGamma_(scene.pov.assumedGamma),
      perThread_(size_t(resolveThreads(s.threads))) {
    preparePhotons(tracer_, scene, s.threads, photons_, mediaPhotons_);
    pretraceRadiosity(tracer_, scene, view_, s, radiosity_);
}

void TileRenderer::renderTile(int t, int worker, ImageF& img, int imgY0, const RecordFn& onRecord) {
    const int x0 = (t % tilesX()) * kTileSize, y0 = (t / tilesX()) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, s_.width), y1 = std::min(y0 + kTileSize, s_.height);
    TraceContext& ctx = perThread_[size_t(worker)];
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            PathInfo info;
            const Vec3 c = renderPixel(tracer_, view_, s_, x, s_.height - 1 - y, ctx, onRecord ? &info : nullptr);
            img.at(x, y - imgY0) = pixelOutput(c, povOutput_, s_.linearOutput, assumedGamma_, s_.fileGamma);
            if (onRecord) onRecord(x, y, info);
        }
}

TraceStats TileRenderer::stats() const {
    TraceStats sum;
    for (const TraceContext& c : perThread_) sum.add(c.stats);
    return sum;
}

ImageF render(const Scene& scene, const Bvh& bvh, const RenderSettings& s, TraceStats& stats,
              const ProgressFn& progress, std::vector<uint8_t>* edgePixels, const RecordFn& onRecord,
              const RowsFn& onRows) {
    ImageF img = ImageF::uninitialized(s.width, s.height);  // every pixel is written below
    const ViewSetup view = resolveView(scene, s);
    // The two passes of adaptive AA (a first sample, then supersampling where the rule says)
    // need a sharp first image: with a lens every pixel takes its blur samples instead (as
    // POV-Ray's focal blur samples every pixel whatever the anti-aliasing).
    const bool twoPass = s.aaEdges && view.aperture <= 0;
    // Primary rays start at the eye unless a lens spreads them or they start on a mesh camera's
    // faces.
    const bool pinholeRays = view.aperture <= 0 && !view.rays.mesh;
    const SharedOrigins origins =
        Tracer::buildSharedOrigins(scene, bvh, pinholeRays ? &view.rays.location : nullptr,
                                   double(s.width) * double(s.height) * double(view.samples), s.threads);
    Tracer tracer(scene, bvh, s, &origins);
    PhotonMap photons, mediaPhotons;  // POV-Ray's photons: shot before the render, read-only during it
    preparePhotons(tracer, scene, s.threads, photons, mediaPhotons);
    IrradianceCache radiosity;  // POV-Ray's radiosity: filled before the final pass, read-only during it
    pretraceRadiosity(tracer, scene, view, s, radiosity);
    // POV-Ray scenes: each final pixel as POV-Ray writes it, sRGB(c^assumed_gamma), before anything
    // reads the image (the PNG stream, feature lines, post filters).
    const bool povOutput = scene.pov.enabled;
    const double assumedGamma = scene.pov.assumedGamma;
    // HDR files (s.linearOutput) take linear light instead, unclamped (docs/aov.md).
    auto pixelOut = [&](Vec3 c) { return pixelOutput(c, povOutput, s.linearOutput, assumedGamma, s.fileGamma); };
    const int tilesX = (s.width + kTile - 1) / kTile, tilesY = (s.height + kTile - 1) / kTile;
    const int tileCount = tilesX * tilesY;
    std::vector<TraceContext> perThread(size_t(resolveThreads(s.threads)));

    // Tiles finished by the first pass; a cancelled render leaves the others black (the image is
    // not zero-filled up front: the render threads are the first to touch it).
    std::vector<uint8_t> tileDone(size_t(tileCount), 0);
    bool firstPass = true;
    // Tiles still to finish per row of tiles (for onRows).
    std::unique_ptr<std::atomic<int>[]> rowTilesLeft;
    if (onRows && !twoPass) {
        rowTilesLeft = std::make_unique<std::atomic<int>[]>(size_t(tilesY));
        for (int r = 0; r < tilesY; ++r) rowTilesLeft[size_t(r)].store(tilesX, std::memory_order_relaxed);
    }
    auto forTiles = [&](const std::function<void(int x, int y, TraceContext&)>& pixel, const ProgressFn& prog) {
        parallelFor(tileCount, s.threads, [&](int t, int w) {
            const int x0 = (t % tilesX) * kTile, y0 = (t / tilesX) * kTile;
            const int x1 = std::min(x0 + kTile, s.width), y1 = std::min(y0 + kTile, s.height);
            // The cancel flag is looked at for every pixel, so a signal stops even a render of one
            // big, slow tile within about a pixel's time; an unfinished tile stays not done.
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    if (cancelled()) return;
                    if (s.inRegion(x, y)) pixel(x, y, perThread[size_t(w)]);
                    else img.at(x, y) = Vec3{};  // outside the part asked for (Start_Row …): black
                }
            if (firstPass) tileDone[size_t(t)] = 1;
            // The last tile of its row: the other tiles' pixels are visible here (acq_rel).
            if (rowTilesLeft && rowTilesLeft[size_t(t / tilesX)].fetch_sub(1, std::memory_order_acq_rel) == 1)
                onRows(img, y0, y1, w);
        }, prog);
        if (firstPass && cancelled())
            for (int t = 0; t < tileCount; ++t) {
                if (tileDone[size_t(t)]) continue;
                const int x0 = (t % tilesX) * kTile, y0 = (t / tilesX) * kTile;
                for (int y = y0; y < std::min(y0 + kTile, s.height); ++y)
                    for (int x = x0; x < std::min(x0 + kTile, s.width); ++x) img.at(x, y) = Vec3{};
            }
        firstPass = false;
    };

    if (!twoPass) {
        forTiles([&](int x, int y, TraceContext& ctx) {
            PathInfo info;
            img.at(x, y) = pixelOut(renderPixel(tracer, view, s, x, s.height - 1 - y, ctx, onRecord ? &info : nullptr));
            if (onRecord) onRecord(x, y, info);
        }, progress);
        if (edgePixels && s.aaEdges) edgePixels->assign(size_t(s.width) * size_t(s.height), 1);  // all fully sampled
    } else {
        // Pass 1: one centre sample per pixel, remembering what it saw.
        RenderSettings one = s;
        one.aa = AaMode::Grid;
        one.spp = 1;
        ViewSetup pinhole = view;
        pinhole.samples = 1;
        pinhole.aperture = 0;
        const bool byColour = s.aaThreshold >= 0;
        // What each centre saw, kept only for a reader: the path rule or the line records (48
        // bytes a pixel to clear and fault in otherwise: 3.7 MB at 320×240).
        const size_t pixels = size_t(s.width) * size_t(s.height);
        std::vector<PathInfo> seen(!byColour || onRecord ? pixels : 0);
        Looks looks;  // the colours POV-Ray's rule compares, first touched by the render threads
        if (byColour) looks.resize(pixels);
        forTiles([&](int x, int y, TraceContext& ctx) {
            const size_t i = size_t(y) * s.width + x;
            const Vec3 c = renderPixel(tracer, pinhole, one, x, s.height - 1 - y, ctx, seen.empty() ? nullptr : &seen[i]);
            img.at(x, y) = pixelOut(c);
            if (byColour) looks[i] = aaLook(povOutput ? povLinearColor(c, assumedGamma) : c, s.aaGamma);
        }, progress ? ProgressFn([&](double f) { progress(0.5 * f); }) : ProgressFn{});
        // A cancelled first pass left pixels unset: nothing is marked (pass 2 stops at once anyway).
        std::vector<uint8_t> mark = cancelled() ? std::vector<uint8_t>(pixels, 0)
                                    : byColour  ? markColourChanges(looks, s.width, s.height, s.aaThreshold)
                                                : markPathChanges(seen, s.width, s.height);
        // Pass 2: full sampling of the marked pixels only.
        forTiles([&](int x, int y, TraceContext& ctx) {
            if (mark[size_t(y) * s.width + x])
                img.at(x, y) = pixelOut(renderPixel(tracer, view, s, x, s.height - 1 - y, ctx));
        }, progress ? ProgressFn([&](double f) { progress(0.5 + 0.5 * f); }) : ProgressFn{});
        if (edgePixels) *edgePixels = std::move(mark);
        if (onRecord)
            for (int y = 0; y < s.height; ++y)
                for (int x = 0; x < s.width; ++x) onRecord(x, y, seen[size_t(y) * s.width + x]);
    }
    for (const TraceContext& c : perThread) stats.add(c.stats);
    return img;
}

}  // namespace rays
