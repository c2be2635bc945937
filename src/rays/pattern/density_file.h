// POV-Ray's density_file pattern (reference 3.5.11.10, "Density_File"): a grid of values read
// from a DF3 file (three big-endian 16-bit sizes nx, ny, nz, then nx·ny·nz values with x fastest,
// 8, 16 or 32 bits each as the file's length says, big-endian, scaled to [0, 1]) laid over the
// unit cube; 0 outside it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rays/math/vec3.h"

namespace rays::pattern {

struct DensityGrid {
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> values;  ///< nx·ny·nz, x fastest, then y, then z

    /// The value at p: 0 outside [0, 1)³. Measured with POV-Ray 3.7's pattern functions on a
    /// 3×2×2 file (tests/pov_density_file_test.cpp): interpolate 0 takes voxel ⌊p·n⌋;
    /// interpolate 1 is trilinear with voxel i at coordinate i (p·n between voxels ⌊p·n⌋ and
    /// ⌊p·n⌋ + 1, the last one's neighbour being voxel 0: the grid wraps); interpolate 2 is
    /// Catmull-Rom's cubic over the four voxels around, wrapping the same way (POV-Ray's values
    /// differ from it in the first cell along x).
    double at(Vec3 p, int interpolate) const;
};

/// Reads a DF3 file's bytes into grid; false with why set when they are not one (too short, a
/// zero size, a length that fits no value size, more than kMaxDensityValues values).
bool readDf3(const std::string& bytes, DensityGrid& grid, std::string& why);

/// The most values a density file may hold (256 MiB of floats).
inline constexpr uint64_t kMaxDensityValues = uint64_t(1) << 26;

}  // namespace rays::pattern
