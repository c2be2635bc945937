// OriginBuffer: candidate lists for rays that start at one point, or run within a small distance
// of such rays: primary rays from a pinhole eye, shadow rays towards a point light. The idea of
// the "light buffer" (Haines and Greenberg, 1986) and of POV-Ray's old vista buffer: the
// directions around the origin are cut into the cells of a cube map, each cell lists the objects
// that some direction of the cell may meet, sorted by a lower bound of their distance from the
// origin along the cell's directions, and a ray tests only its cell's objects, nearest first,
// stopping at the first object that cannot lie before its current hit (closest hit) or its end
// (any hit).
//
// Two resolutions: an object that would fill many fine cells (a big or close object) is listed in
// the coarse cells instead, so that no object is copied into thousands of lists.
//
// Conservative by construction: every bound is grown by `dilation` (for rays that run within that
// distance of a ray from the origin, such as shadow rays that leave a surface offset along its
// normal) and by a margin far above the rounding of the double arithmetic of the build. The lists
// only choose which exact tests run; results are those of the exact tests.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rays/geometry/ray.h"
#include "rays/math/vec3.h"

namespace rays {

class OriginBuffer {
public:
    /// What the buffer knows of an object: a bounding sphere or a box, and for flat objects their
    /// plane (every point x of the object has dot(normal, x) = offset, normal unit length).
    struct Bound {
        uint32_t id = 0;        ///< the caller's index, returned in the entries
        bool isSphere = false;  ///< centre and radius bound the object; otherwise lo and hi do
        Vec3 centre;
        double radius = 0;
        Vec3 lo, hi;
        bool flat = false;
        Vec3 normal;
        double offset = 0;
    };
    /// A listed object: minDist is at most the distance from the origin of any point of the grown
    /// object whose direction lies in the cell.
    struct Entry {
        float minDist;
        uint32_t id;
    };
    /// The entries of one cell, sorted by increasing minDist.
    struct Span {
        const Entry* first = nullptr;
        const Entry* last = nullptr;
    };

    static constexpr int kFineResolution = 256;  ///< cells per face edge
    static constexpr int kCoarseResolution = 8;
    /// Objects covering more fine cells than this are listed in the coarse cells.
    static constexpr size_t kMaxFineCells = 1024;

    /// Builds the lists for rays from origin over bounds (replaces any previous content).
    void build(const std::vector<Bound>& bounds, Vec3 origin, double dilation);
    bool empty() const { return !built_; }
    Vec3 origin() const { return origin_; }
    double dilation() const { return dilation_; }
    /// The lists a direction falls in: its fine and its coarse cell.
    struct Cells {
        Span fine, coarse;
        bool valid = false;  ///< false for a zero or non-finite direction, or an empty buffer
    };
    /// The cells of direction dir (any length).
    Cells cells(const Vec3& dir) const;

private:
    /// The part of a face whose cells list something: cells [i0, i0 + w) x [j0, j0 + h), numbered
    /// from base row by row.
    struct Window {
        int i0 = 0, j0 = 0, w = 0, h = 0;
        uint32_t base = 0;
    };
    struct Level {
        int n = 0;                    ///< cells per face edge
        Window face[6];
        std::vector<uint32_t> start;  ///< per window cell, offsets into entries (+ 1 at the end)
        std::vector<Entry> entries;
        Span cell(int f, int i, int j) const {
            const Window& w = face[f];
            const unsigned di = unsigned(i - w.i0), dj = unsigned(j - w.j0);
            if (di >= unsigned(w.w) || dj >= unsigned(w.h)) return {};
            const size_t c = w.base + size_t(dj) * unsigned(w.w) + di;
            return {entries.data() + start[c], entries.data() + start[c + 1]};
        }
    };
    Vec3 origin_;
    double dilation_ = 0;
    Level fine_, coarse_;
    bool built_ = false;
};

}  // namespace rays
