// The uv lookup of POV-Ray's mesh_camera distribution 3: which face of the camera meshes has a
// given (u, v) inside its uv triangle. A uniform grid over the uvs' bounds lists, per cell, the
// faces whose uv bounds overlap it, in face order, so the first face holding the point (POV-Ray 3.7
// takes "the first face to match") is the first one found.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rays {

class UvFaceGrid {
public:
    UvFaceGrid() = default;
    /// uvs: six values per face (u0 v0 u1 v1 u2 v2), faces in order. Faces with no uv area or
    /// with values that are not finite are never found.
    explicit UvFaceGrid(std::vector<double> uvs);

    /// The first face whose uv triangle holds (u, v) (its edges included; a point on an edge two
    /// faces share is in one of them), with the point's barycentric weights of the face's corners
    /// in w; −1 when none does.
    int64_t find(double u, double v, double w[3]) const;

    size_t faceCount() const { return uv_.size() / 6; }
    size_t memoryBytes() const;

private:
    /// The cells a face's uv bounds cover (inclusive ranges); false for a face never found.
    bool cellRange(size_t face, int& i0, int& i1, int& j0, int& j1) const;
    int cellU(double u) const;
    int cellV(double v) const;

    std::vector<double> uv_;
    double u0_ = 0, v0_ = 0;        ///< the grid's lower corner
    double scaleU_ = 0, scaleV_ = 0; ///< cells per uv unit
    int nu_ = 0, nv_ = 0;           ///< cells across, down
    std::vector<uint32_t> cellStart_;  ///< nu_·nv_ + 1 offsets into cellFaces_
    std::vector<uint32_t> cellFaces_;  ///< each cell's faces, ascending
};

}  // namespace rays
