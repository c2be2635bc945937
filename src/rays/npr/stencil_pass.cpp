#include "rays/npr/stencil_pass.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <vector>

#include "rays/npr/edge_classify.h"
#include "rays/npr/stencil.h"
#include "rays/npr/tap_models.h"
#include "rays/render/renderer.h"

namespace rays {
namespace {

// Per stencil offset (the same for every pixel): the four pixel centres around it, as indices
// into the (2·reach + 1)² window around the pixel, and its bilinear weights.
struct Tap {
    int cell[4];
    float w[4];
    double dx, dy;
};

constexpr uint8_t kRight = 1, kDown = 2;  // the pair with the right / lower neighbour differs

}  // namespace

struct StencilPass::Impl {
    // One worker's scratch space.
    struct Scratch {
        std::vector<uint8_t> pairs;  // row-dilated differing pairs of the rows a band looks at
        std::vector<uint8_t> mark;   // candidates of one row
        std::vector<uint8_t> full;   // edge types between the centre and each window cell
        PathInfo other;
    };

    const RenderSettings& s;
    const EdgeSettings& e;
    const LineRecords& records;
    const Tracer tracer;
    const CameraRays cam;
    const EdgeThresholds th;
    const bool shadows, secondary;
    int n = 0, reach = 0, side = 0, bandRows = 0, bands = 0;
    std::vector<Tap> taps;
    std::vector<TraceContext> ctx;  // per worker
    std::vector<Scratch> scratch;   // per worker
    std::unique_ptr<std::atomic<uint8_t>[]> rowDone, bandTaken;
    LineCoverage lc;

    Impl(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const EdgeSettings& edges,
         const LineRecords& recs)
        : s(settings),
          e(edges),
          records(recs),
          tracer(scene, bvh, settings),
          cam(CameraRays(scene.cameras.at(size_t(settings.cameraIndex)))),
          th(thresholdsFor(edges)),
          shadows(edges.types & kEdgeShadow),
          secondary(edges.types & kEdgeReflection) {
        const double radius = stencilRadius(e.width);
        const std::vector<StencilOffset> stencil = makeStencil(radius);
        n = int(stencil.size());
        // Stencil positions lie within R pixels of the centre, so their four surrounding pixel
        // centres lie within ⌈R⌉.
        reach = int(std::ceil(radius));
        side = 2 * reach + 1;
        for (const StencilOffset& o : stencil) {
            const double px = 0.5 + o.dx, py = 0.5 - o.dy;  // relative to the pixel, rows down
            const int ix = int(std::floor(px - 0.5)), iy = int(std::floor(py - 0.5));
            const double fx = px - 0.5 - ix, fy = py - 0.5 - iy;
            auto at = [&](int dx, int dy) { return (dy + reach) * side + dx + reach; };
            taps.push_back({{at(ix, iy), at(ix + 1, iy), at(ix, iy + 1), at(ix + 1, iy + 1)},
                            {float((1 - fx) * (1 - fy)), float(fx * (1 - fy)), float((1 - fx) * fy), float(fx * fy)},
                            o.dx,
                            o.dy});
        }
        // Bands of 16 rows (more for wide lines: each band also reads `reach` rows around it).
        bandRows = std::max(16, 4 * reach);
        bands = (s.height + bandRows - 1) / bandRows;
        const size_t workers = size_t(resolveThreads(s.threads));
        ctx.resize(workers);
        scratch.resize(workers);
        rowDone = std::make_unique<std::atomic<uint8_t>[]>(size_t(s.height));
        bandTaken = std::make_unique<std::atomic<uint8_t>[]>(size_t(bands));
        for (int y = 0; y < s.height; ++y) rowDone[size_t(y)].store(0, std::memory_order_relaxed);
        for (int b = 0; b < bands; ++b) bandTaken[size_t(b)].store(0, std::memory_order_relaxed);
        lc = LineCoverage::empty(s.width, s.height);
    }

    // The rows band b reads: its own and `reach` around them, plus one below for vertical pairs.
    void bandRange(int b, int& first, int& end) const {
        first = std::max(0, b * bandRows - reach);
        end = std::min(s.height, (b + 1) * bandRows + reach + 1);
    }

    bool bandReady(int b) const {
        int first, end;
        bandRange(b, first, end);
        for (int y = first; y < end; ++y)
            if (!rowDone[size_t(y)].load(std::memory_order_acquire)) return false;
        return true;
    }

    void takeAndDraw(int b, int worker) {
        if (bandTaken[size_t(b)].load(std::memory_order_relaxed)) return;
        if (bandTaken[size_t(b)].exchange(1, std::memory_order_acq_rel)) return;
        drawBand(b, worker);
    }

    // Candidates are the pixels whose window holds both pixels of a neighbour pair that differs:
    // the only places where stencil taps can find an edge. A window centred at column c holds
    // columns c − reach .. c + reach: both pixels of the pair (x, x + 1) when
    // x + 1 − reach ≤ c ≤ x + reach, the pixel x of a vertical pair when x − reach ≤ c ≤ x + reach;
    // rows likewise.
    void drawBand(int b, int worker) {
        const int W = s.width, H = s.height;
        const int y0 = b * bandRows, y1 = std::min(H, y0 + bandRows);
        const int k0 = std::max(0, y0 - reach), k1 = std::min(H, y1 + reach);
        Scratch& sc = scratch[size_t(worker)];
        sc.pairs.assign(size_t(k1 - k0) * size_t(W), 0);
        sc.mark.resize(size_t(W));
        sc.full.resize(size_t(side) * size_t(side));
        const LineRecords::RecordVector& rec = records.rec;
        for (int k = k0; k < k1; ++k) {
            const EdgeRecord* row = &rec[size_t(k) * W];
            uint8_t* t = &sc.pairs[size_t(k - k0) * W];
            for (int x = 0; x < W; ++x) {
                if (x + 1 < W && (classifyPair(row[x], row[x + 1], th) & e.types))
                    for (int c = std::max(0, x + 1 - reach); c <= std::min(W - 1, x + reach); ++c) t[c] |= kRight;
                if (k + 1 < H && (classifyPair(row[x], row[size_t(x) + W], th) & e.types))
                    for (int c = std::max(0, x - reach); c <= std::min(W - 1, x + reach); ++c) t[c] |= kDown;
            }
        }
        for (int y = y0; y < y1; ++y) {
            uint8_t* o = sc.mark.data();
            std::memset(o, 0, size_t(W));
            // Row pairs (k, k + 1) with k + 1 − reach ≤ y ≤ k + reach; single rows within reach.
            // Eight bytes at a time; any non-zero value marks a candidate.
            for (int k = std::max(0, y - reach); k <= std::min(H - 1, y + reach); ++k) {
                const uint8_t* t = &sc.pairs[size_t(k - k0) * W];
                const uint8_t want = k <= y + reach - 1 ? (kRight | kDown) : kRight;
                const uint64_t want8 = want * 0x0101010101010101ull;
                int x = 0;
                for (; x + 8 <= W; x += 8) {
                    uint64_t a, c;
                    std::memcpy(&a, o + x, 8);
                    std::memcpy(&c, t + x, 8);
                    a |= c & want8;
                    std::memcpy(o + x, &a, 8);
                }
                for (; x < W; ++x) o[x] |= t[x] & want;
            }
            for (int x = 0; x < W; ++x)
                if (o[x])
                    lc.coverage[size_t(y) * W + x] = float(stencilStrength(differingTaps(x, y, sc, ctx[size_t(worker)]), n));
        }
    }

    // How many of the n stencil taps around pixel (x, y) see an enabled edge type against it (m).
    int differingTaps(int x, int y, Scratch& sc, TraceContext& tc) {
        const LineRecords::RecordVector& rec = records.rec;
        const SurfaceIds& ids = records.ids;
        const EdgeRecord& centre = rec[size_t(y) * s.width + x];
        // The record at window cell k (clamped to the image).
        auto cell = [&](int k) -> const EdgeRecord& {
            const int cy = std::clamp(y + k / side - reach, 0, s.height - 1);
            const int cx = std::clamp(x + k % side - reach, 0, s.width - 1);
            return rec[size_t(cy) * s.width + size_t(cx)];
        };
        std::vector<uint8_t>& full = sc.full;
        if (x >= reach && x < s.width - reach && y >= reach && y < s.height - reach) {
            const EdgeRecord* corner = &rec[size_t(y - reach) * s.width + size_t(x - reach)];
            uint8_t* f = full.data();
            for (int dy = 0; dy < side; ++dy, corner += s.width)
                for (int dx = 0; dx < side; ++dx) *f++ = uint8_t(classifyPair(centre, corner[dx], th));
        } else {
            for (int k = 0; k < side * side; ++k) full[size_t(k)] = uint8_t(classifyPair(centre, cell(k), th));
        }
        const uint8_t types = uint8_t(e.types);
        int m = 0;
        for (const Tap& tap : taps) {
            // Reuse primary hits: when the four pixel centres around the stencil position agree,
            // the stencil ray would see the same; cast it otherwise.
            const uint8_t a = full[size_t(tap.cell[0])] & types, b = full[size_t(tap.cell[1])] & types;
            const uint8_t c = full[size_t(tap.cell[2])] & types, d = full[size_t(tap.cell[3])] & types;
            const uint8_t any = a | b | c | d, all = a & b & c & d;
            if (any == 0) continue;
            if (all != 0 && any == all) {
                ++m;
                continue;
            }
            // Mixed cell: the edge runs between its centres. Far from the midway contour of the
            // bilinear indicator the answer is clear; resolve it only near the contour.
            const float v = (a ? tap.w[0] : 0.0f) + (b ? tap.w[1] : 0.0f) + (c ? tap.w[2] : 0.0f) + (d ? tap.w[3] : 0.0f);
            if (v <= 0.25f) continue;
            if (v >= 0.75f) {
                ++m;
                continue;
            }
            const Ray r = cam.rayThrough(x + 0.5 + tap.dx, s.height - 1 - y + 0.5 + tap.dy, s.width, s.height);
            const uint8_t fullAny = full[size_t(tap.cell[0])] | full[size_t(tap.cell[1])] | full[size_t(tap.cell[2])] |
                                    full[size_t(tap.cell[3])];
            if (fullAny == any && (any == kEdgeCrease || (any == kEdgeShadow && shadows))) {
                // One surface around the tap, two facets or one lit differently: decide it from
                // the records' tangent planes (tap_models.h) when they are conclusive.
                const uint8_t v4[4] = {a, b, c, d};
                int same = -1, other = -1;  // the heaviest cell of each kind
                for (int q = 0; q < 4; ++q) {
                    int& best = v4[q] ? other : same;
                    if (best < 0 || tap.w[q] > tap.w[best]) best = q;
                }
                const EdgeRecord& near0 = cell(tap.cell[same]);
                const EdgeRecord& near1 = cell(tap.cell[other]);
                if (any == kEdgeCrease) {
                    const int sideSeen = creaseSide(r, near0, near1);
                    if (sideSeen >= 0) {
                        m += sideSeen;
                        continue;
                    }
                } else {
                    const EdgeRecord& plane = tap.w[same] >= tap.w[other] ? near0 : near1;
                    const double t = tangentPlaneT(r, plane);
                    if (t > 0) {
                        if (tracer.blockedLightsAt(r.at(t), plane.normal(), tc) != centre.blocked) ++m;
                        continue;
                    }
                }
            }
            // Shadow rays only where the shadow count changes nearby and nothing else already
            // separates the two samples.
            tracer.probe(r, false, secondary, tc, sc.other);
            EdgeRecord er = toEdgeRecord(sc.other, ids);
            er.blocked = centre.blocked;
            if (classifyPair(centre, er, th) & e.types) {
                ++m;
            } else if (shadows && (any & kEdgeShadow) && er.surface >= 0) {
                if (tracer.blockedLightsAt(sc.other.hitPoint(), sc.other.hitNormal(), tc) != centre.blocked) ++m;
            }
        }
        return m;
    }
};

StencilPass::StencilPass(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                         const LineRecords& records)
    : impl_(std::make_unique<Impl>(scene, bvh, s, e, records)) {}

StencilPass::~StencilPass() = default;

void StencilPass::rowsDone(int y0, int y1, int worker) {
    Impl& p = *impl_;
    y0 = std::max(0, y0);
    y1 = std::min(p.s.height, y1);
    if (y0 >= y1) return;
    for (int y = y0; y < y1; ++y) p.rowDone[size_t(y)].store(1, std::memory_order_release);
    // Bands that read any of these rows.
    const int bFirst = std::max(0, (y0 - p.reach - 1) / p.bandRows);
    const int bLast = std::min(p.bands - 1, (y1 - 1 + p.reach) / p.bandRows);
    for (int b = bFirst; b <= bLast; ++b)
        if (p.bandReady(b)) p.takeAndDraw(b, worker);
}

LineCoverage StencilPass::finish(TraceStats& stats) {
    Impl& p = *impl_;
    parallelFor(p.bands, p.s.threads, [&](int b, int w) { p.takeAndDraw(b, w); });
    for (const TraceContext& c : p.ctx) stats.add(c.stats);
    return std::move(p.lc);
}

}  // namespace rays
