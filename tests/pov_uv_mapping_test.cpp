// POV-Ray's uv_mapping (reference, "UV Mapping"): a uv-mapped pigment or texture pattern is looked
// up at the surface's (u, v, 0) instead of the point, and the object's transformations leave it
// where it is. Measured with POV-Ray 3.7 on a mesh2 triangle <0,0,0>, <1,0,0>, <0,1,0> whose
// uv_vectors are <0,0>, <1,1>, <1,-1>: a `function { x }` pigment grows as x + y across it and a
// `function { y }` one as x − y, as barycentric interpolation of the vertices' uvs gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

using test::buildPov;

// The triangle (moved by `after`, written after its texture) seen head-on through a 20×20
// orthographic window over the unit square, lit by ambient light only.
std::string triangle(const std::string& texture, const std::string& after = "", const std::string& objectUV = "") {
    return "global_settings { assumed_gamma 1 }\n"
           "camera { orthographic location <0.5,0.5,-5> look_at <0.5,0.5,0> right x up y }\n"
           "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
           "  uv_vectors { 3, <0,0>, <1,1>, <1,-1> } face_indices { 1, <0,1,2> } uv_indices { 1, <0,1,2> }\n"
           "  " + objectUV + " " + texture + " " + after + " }\n";
}

const std::string kRedU = "pigment { function { x } color_map { [0 rgb 0] [1 rgb <1,0,0>] } } finish { ambient 1 diffuse 0 }";

// The red channel at the centre of pixel (x, y) of the 20×20 render (y from the top), linear (the
// render is sRGB-encoded for output, as POV-Ray 3.7 encodes assumed_gamma 1 scenes), and the u
// there: x + y of the point, y counted up.
double redAt(const ImageF& img, int x, int y) {
    const double v = img.at(x, y).x;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double uAt(int x, int y) { return (x + 0.5) / 20 + (19 - y + 0.5) / 20; }

// Pixels (x, y from the top) whose red is scale·(u + shift), u = x + y of the pixel centre.
void expectU(const ImageF& img, double scale = 1, double shift = 0,
             std::initializer_list<std::pair<int, int>> pixels = {{2, 17}, {10, 15}, {4, 8}, {12, 12}}) {
    for (auto [x, y] : pixels) {
        SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
        EXPECT_NEAR(redAt(img, x, y), std::min(1.0, scale * (uAt(x, y) + shift)), 0.02);
    }
}

TEST(PovUvMapping, PigmentFollowsTheMeshUVs) {
    const ImageF img = test::renderPov(buildPov(triangle("texture { " + std::string("pigment { uv_mapping function { x } "
                                                         "color_map { [0 rgb 0] [1 rgb <1,0,0>] } } finish { ambient 1 diffuse 0 } }"))), 20, 20);
    expectU(img);
    // Without uv_mapping the pigment follows the point (x alone).
    const ImageF plain = test::renderPov(buildPov(triangle("texture { " + kRedU + " }")), 20, 20);
    EXPECT_NEAR(redAt(plain, 10, 15), 10.5 / 20, 0.02);
}

TEST(PovUvMapping, TextureAndObjectUvMapping) {
    expectU(test::renderPov(buildPov(triangle("texture { uv_mapping " + kRedU + " }")), 20, 20));
    expectU(test::renderPov(buildPov(triangle("texture { " + kRedU + " }", "", "uv_mapping")), 20, 20));
}

TEST(PovUvMapping, TransformsInTheTextureMoveItAndTheObjectsDoNot) {
    // `scale 2` in the texture halves the value at each uv; the object's translate along its
    // normal changes nothing.
    expectU(test::renderPov(buildPov(triangle("texture { uv_mapping " + kRedU + " scale 2 }", "translate z")), 20, 20), 0.5);
    // Moved 0.3 to the right, the triangle keeps its uvs: u = (x − 0.3) + y where it now is (a
    // pigment placed by the point would read x − 0.3 alone).
    expectU(test::renderPov(buildPov(triangle("texture { uv_mapping " + kRedU + " }", "translate <0.3,0,0>")), 20, 20), 1,
            -0.3, {{10, 15}, {12, 12}, {16, 16}});
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
