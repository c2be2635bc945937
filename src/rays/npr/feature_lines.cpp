#include "rays/npr/feature_lines.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "rays/npr/edge_classify.h"
#include "rays/npr/stencil.h"
#include "rays/npr/surfaces.h"
#include "rays/npr/tap_models.h"

namespace rays {
namespace {

constexpr int kRowBlock = 8;  // rows per parallel work item

// Probes the centre ray of every pixel.
void probeCentres(const Tracer& tracer, const Camera& cam, const RenderSettings& s, const EdgeSettings& e,
                  std::vector<TraceContext>& ctx, LineRecords& out) {
    const bool shadows = e.types & kEdgeShadow, secondary = e.types & kEdgeReflection;
    parallelFor((s.height + kRowBlock - 1) / kRowBlock, s.threads, [&](int block, int w) {
        PathInfo info;
        for (int y = block * kRowBlock; y < std::min(s.height, (block + 1) * kRowBlock); ++y)
            for (int x = 0; x < s.width; ++x) {
                tracer.probe(cam.rayThrough(x + 0.5, s.height - 1 - y + 0.5, s.width, s.height), shadows, secondary,
                             ctx[size_t(w)], info);
                out.store(x, y, info);
            }
    });
}

// Anti-aliased disc stamp: coverage max(·, clamp(w/2 + ½ − d, 0, 1)) around (cx, cy).
void stamp(LineCoverage& lc, double cx, double cy, double width) {
    const double reach = width / 2 + 0.5;
    const int x0 = std::max(0, int(std::floor(cx - reach))), x1 = std::min(lc.width - 1, int(std::ceil(cx + reach)));
    const int y0 = std::max(0, int(std::floor(cy - reach))), y1 = std::min(lc.height - 1, int(std::ceil(cy + reach)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            const float c = float(std::clamp(reach - d, 0.0, 1.0));
            float& dst = lc.coverage[size_t(y) * lc.width + x];
            dst = std::max(dst, c);
        }
}

// Image method: an edge between two neighbouring pixels is stamped at their shared midpoint.
void imageLines(LineCoverage& lc, const LineRecords::RecordVector& rec, const EdgeSettings& e) {
    const EdgeThresholds th = thresholdsFor(e);
    const int W = lc.width, H = lc.height;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const EdgeRecord& p = rec[size_t(y) * W + x];
            if (x + 1 < W && (classifyPair(p, rec[size_t(y) * W + x + 1], th) & e.types))
                stamp(lc, x + 1.0, y + 0.5, e.width);
            if (y + 1 < H && (classifyPair(p, rec[size_t(y + 1) * W + x], th) & e.types))
                stamp(lc, x + 0.5, y + 1.0, e.width);
        }
}

// Pixels whose stencil window (the records within `reach`) holds both pixels of a neighbour pair
// that differs: the only places where stencil taps can find an edge. Creases and depth jumps are
// sharp, so adjacent pixel centres already show the full normal angle or depth step; the
// thresholds need no relaxing.
using Mask = std::vector<uint8_t, tribvh::HugePageAllocator<uint8_t>>;  // warm memory when prewarmed
Mask candidates(const LineRecords::RecordVector& rec, int W, int H, const EdgeSettings& e, int reach, int threads) {
    const EdgeThresholds th = thresholdsFor(e);
    constexpr uint8_t kRight = 1, kDown = 2;  // the pair with the right / lower neighbour differs
    Mask diff(rec.size(), 0), tmp(rec.size(), 0), out(rec.size(), 0);
    const int blocks = (H + kRowBlock - 1) / kRowBlock;
    parallelFor(blocks, threads, [&](int block, int) {
        for (int y = block * kRowBlock; y < std::min(H, (block + 1) * kRowBlock); ++y)
            for (int x = 0; x < W; ++x) {
                const EdgeRecord& p = rec[size_t(y) * W + x];
                uint8_t bits = 0;
                if (x + 1 < W && (classifyPair(p, rec[size_t(y) * W + x + 1], th) & e.types)) bits |= kRight;
                if (y + 1 < H && (classifyPair(p, rec[size_t(y + 1) * W + x], th) & e.types)) bits |= kDown;
                diff[size_t(y) * W + x] = bits;
            }
    });
    // Separable dilation. A window centred at column c holds columns c - reach .. c + reach: both
    // pixels of the pair (x, x + 1) when x + 1 - reach <= c <= x + reach, the pixel x of a
    // vertical pair when x - reach <= c <= x + reach. Rows likewise.
    parallelFor(blocks, threads, [&](int block, int) {
        for (int y = block * kRowBlock; y < std::min(H, (block + 1) * kRowBlock); ++y) {
            const uint8_t* d = &diff[size_t(y) * W];
            uint8_t* t = &tmp[size_t(y) * W];
            for (int x = 0; x < W; ++x) {
                if (d[x] & kRight)
                    for (int k = std::max(0, x + 1 - reach); k <= std::min(W - 1, x + reach); ++k) t[k] |= kRight;
                if (d[x] & kDown)
                    for (int k = std::max(0, x - reach); k <= std::min(W - 1, x + reach); ++k) t[k] |= kDown;
            }
        }
    });
    parallelFor(blocks, threads, [&](int block, int) {
        for (int y = block * kRowBlock; y < std::min(H, (block + 1) * kRowBlock); ++y) {
            uint8_t* o = &out[size_t(y) * W];
            // Row pairs (k, k + 1) with k + 1 - reach <= y <= k + reach; single rows within reach.
            // Bits kept as they are (any non-zero value marks a candidate), eight bytes at a time.
            for (int k = std::max(0, y - reach); k <= std::min(H - 1, y + reach); ++k) {
                const uint8_t* t = &tmp[size_t(k) * W];
                const uint8_t want = k <= y + reach - 1 ? (kRight | kDown) : kRight;
                const uint64_t want8 = want * 0x0101010101010101ull;
                int x = 0;
                for (; x + 8 <= W; x += 8) {
                    uint64_t a, b;
                    std::memcpy(&a, o + x, 8);
                    std::memcpy(&b, t + x, 8);
                    a |= b & want8;
                    std::memcpy(o + x, &a, 8);
                }
                for (; x < W; ++x) o[x] |= t[x] & want;
            }
        }
    });
    return out;
}

}  // namespace

LineRecords::LineRecords(const Scene& scene, int w, int h) : LineRecords(computeSurfaceIds(scene), w, h) {}

LineRecords::LineRecords(SurfaceIds surfaceIds, int w, int h)
    : ids(std::move(surfaceIds)), width(w), height(h), rec(size_t(w) * size_t(h)) {}

bool renderRecordsAreCentred(const Scene& scene, const RenderSettings& s) {
    const Camera& cam = scene.cameras.at(size_t(s.cameraIndex));
    const double aperture = s.aperture >= 0 ? s.aperture : cam.aperture;
    return s.aa == AaMode::Grid && s.spp == 1 && aperture <= 0 && !s.aaEdges &&
           (s.shading == ShadingModel::BlinnPhong || s.shading == ShadingModel::CookTorrance);
}

LineCoverage drawFeatureLines(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                              const LineRecords* centre, TraceStats& stats) {
    LineCoverage lc;
    lc.width = s.width;
    lc.height = s.height;
    lc.coverage.assign(size_t(s.width) * size_t(s.height), 0.0f);
    if (!e.enabled()) return lc;
    const Tracer tracer(scene, bvh, s);
    const Camera& cam = scene.cameras.at(size_t(s.cameraIndex));
    std::vector<TraceContext> ctx(size_t(resolveThreads(s.threads)));
    std::unique_ptr<LineRecords> probed;
    if (!centre) {
        probed = std::make_unique<LineRecords>(scene, s.width, s.height);
        probeCentres(tracer, cam, s, e, ctx, *probed);
        centre = probed.get();
    }
    const SurfaceIds& ids = centre->ids;
    const LineRecords::RecordVector& rec = centre->rec;

    if (e.method == EdgeMethod::Image) {
        imageLines(lc, rec, e);
    } else {
        const double radius = stencilRadius(e.width);
        const std::vector<StencilOffset> stencil = makeStencil(radius);
        const int n = int(stencil.size());
        const Mask cand = candidates(rec, s.width, s.height, e, int(std::ceil(radius)), s.threads);
        const EdgeThresholds th = thresholdsFor(e);
        const bool shadows = e.types & kEdgeShadow, secondary = e.types & kEdgeReflection;
        // Stencil positions lie within R pixels of the centre, so their four surrounding pixel
        // centres lie within ⌈R⌉.
        const int reach = int(std::ceil(radius));
        const int side = 2 * reach + 1;
        // Per stencil offset (the same for every pixel): the four pixel centres around it, as
        // indices into the window, and its bilinear weights.
        struct Tap {
            int cell[4];
            float w[4];
            double dx, dy;
        };
        std::vector<Tap> taps;
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
        parallelFor((s.height + kRowBlock - 1) / kRowBlock, s.threads, [&](int block, int w) {
            PathInfo other;
            // Between the centre and the record at window cell k: all edge types.
            std::vector<uint8_t> full(size_t(side) * side);
            const uint8_t types = uint8_t(e.types);
            for (int y = block * kRowBlock; y < std::min(s.height, (block + 1) * kRowBlock); ++y)
                for (int x = 0; x < s.width; ++x) {
                    if (!cand[size_t(y) * s.width + x]) continue;
                    const EdgeRecord& centre = rec[size_t(y) * s.width + x];
                    // The record at window cell k (clamped to the image).
                    auto cell = [&](int k) -> const EdgeRecord& {
                        const int cy = std::clamp(y + k / side - reach, 0, s.height - 1);
                        const int cx = std::clamp(x + k % side - reach, 0, s.width - 1);
                        return rec[size_t(cy) * s.width + size_t(cx)];
                    };
                    if (x >= reach && x < s.width - reach && y >= reach && y < s.height - reach) {
                        const EdgeRecord* corner = &rec[size_t(y - reach) * s.width + size_t(x - reach)];
                        uint8_t* f = full.data();
                        for (int dy = 0; dy < side; ++dy, corner += s.width)
                            for (int dx = 0; dx < side; ++dx) *f++ = uint8_t(classifyPair(centre, corner[dx], th));
                    } else {
                        for (int k = 0; k < side * side; ++k) full[size_t(k)] = uint8_t(classifyPair(centre, cell(k), th));
                    }
                    int m = 0;
                    for (const Tap& tap : taps) {
                        // Reuse primary hits: when the four pixel centres around the stencil
                        // position agree, the stencil ray would see the same; cast it otherwise.
                        const uint8_t a = full[size_t(tap.cell[0])] & types, b = full[size_t(tap.cell[1])] & types;
                        const uint8_t c = full[size_t(tap.cell[2])] & types, d = full[size_t(tap.cell[3])] & types;
                        const uint8_t any = a | b | c | d, all = a & b & c & d;
                        if (any == 0) continue;
                        if (all != 0 && any == all) {
                            ++m;
                            continue;
                        }
                        // Mixed cell: the edge runs between its centres. Far from the midway
                        // contour of the bilinear indicator the answer is clear; cast only near it.
                        const float v = (a ? tap.w[0] : 0.0f) + (b ? tap.w[1] : 0.0f) + (c ? tap.w[2] : 0.0f) + (d ? tap.w[3] : 0.0f);
                        if (v <= 0.25f) continue;
                        if (v >= 0.75f) {
                            ++m;
                            continue;
                        }
                        const StencilOffset o{tap.dx, tap.dy};
                        const Ray r = cam.rayThrough(x + 0.5 + o.dx, s.height - 1 - y + 0.5 + o.dy, s.width, s.height);
                        const uint8_t fullAny = full[size_t(tap.cell[0])] | full[size_t(tap.cell[1])] |
                                                full[size_t(tap.cell[2])] | full[size_t(tap.cell[3])];
                        if (fullAny == any && (any == kEdgeCrease || (any == kEdgeShadow && shadows))) {
                            // One surface around the tap, two facets or one lit differently:
                            // decide it from the records' tangent planes (tap_models.h) when
                            // they are conclusive.
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
                                    const Vec3 n{plane.n[0], plane.n[1], plane.n[2]};
                                    if (tracer.blockedLightsAt(r.at(t), n, ctx[size_t(w)]) != centre.blocked) ++m;
                                    continue;
                                }
                            }
                        }
                        // Shadow rays only where the shadow count changes nearby and nothing else
                        // already separates the two samples.
                        tracer.probe(r, false, secondary, ctx[size_t(w)], other);
                        EdgeRecord er = toEdgeRecord(other, ids);
                        er.blocked = centre.blocked;
                        if (classifyPair(centre, er, th) & e.types) {
                            ++m;
                        } else if (shadows && (any & kEdgeShadow) && er.surface >= 0) {
                            if (tracer.blockedLightsAt(other.hitPoint(), other.hitNormal(), ctx[size_t(w)]) != centre.blocked) ++m;
                        }
                    }
                    lc.coverage[size_t(y) * s.width + x] = float(stencilStrength(m, n));
                }
        });
    }
    for (const TraceContext& c : ctx) stats.add(c.stats);
    return lc;
}

void compositeLines(ImageF& img, const LineCoverage& lines, const EdgeSettings& e, int threads) {
    const int rows = img.height;
    parallelFor((rows + kRowBlock - 1) / kRowBlock, threads, [&](int block, int) {
        const size_t begin = size_t(block) * kRowBlock * size_t(img.width);
        const size_t end = std::min(img.pixels.size(), begin + size_t(kRowBlock) * size_t(img.width));
        for (size_t i = begin; i < end; ++i) {
            const double c = lines.coverage[i];
            if (c == 0 && !e.linesOnly) continue;
            const Vec3 base = e.linesOnly ? Vec3(1.0) : img.pixels[i];
            img.pixels[i] = (1 - c) * base + c * e.color;
        }
    });
}

Image8 coverageImage(const LineCoverage& lines) {
    Image8 out(lines.width, lines.height, 1);
    for (size_t i = 0; i < lines.coverage.size(); ++i) out.pixels[i] = toByte(lines.coverage[i]);
    return out;
}

}  // namespace rays
