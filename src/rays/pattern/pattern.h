// Pattern types (POV-Ray 3.7 reference, "Patterns"): each maps a point of pattern space to a value
// in [0, 1] (before the wave), or, for the block patterns (checker, hexagon, brick, square,
// triangular, cubic), to the index of one of their two to six colours or pigments.
#pragma once
#include <cstdint>

#include "rays/fn/program.h"
#include "rays/math/vec3.h"
#include "rays/pattern/crackle.h"
#include "rays/pattern/density_file.h"
#include "rays/pattern/noise.h"
#include "rays/pattern/object_pattern.h"
#include "rays/pattern/pavement.h"
#include "rays/pattern/quilted.h"
#include "rays/pattern/slope.h"

namespace rays::pattern {

enum class PatternKind : uint8_t {
    Solid,  ///< no pattern: one colour
    Checker, Hexagon, Brick, Square, Triangular, Cubic,  // block patterns
    Gradient, Radial, Onion, Spherical, Cylindrical, Planar, Boxed, Leopard,
    Bozo, Granite, Marble, Wood, Agate, Wrinkles, Crackle,
    Ripples, Waves, Dents,  ///< look-alikes of POV-Ray's (pattern/ripples.h)
    Cells,     ///< one random value per unit cube
    Mandel,    ///< the Mandelbrot set in the x-y plane (exponent, exterior and interior colouring)
    Julia,     ///< a Julia set in the x-y plane: mandel's iteration with a fixed c, z starting at the point
    Magnet,    ///< fractint's magnet 1 or 2, mandel or julia type (pattern/magnet.h)
    Spiral1,   ///< a spiral of N arms winding around z, one turn per unit along z
    Spiral2,   ///< two spirals crossing: spiral1's triangle plus rings round z
    Quilted,   ///< unit cubes rising from their centres along a cubic curve (pattern/quilted.h)
    Function,  ///< a user function of x, y, z (`function { ... }`), run on rays/fn's machine
    Slope,     ///< the surface normal's angle to a direction, and the altitude (pattern/slope.h)
    Aoi,       ///< the angle of incidence: between the normal facing the viewer and the ray, over π
    PigmentPattern,  ///< a pigment's grey (PigmentTable::rawValue; PatternParams::source)
    Average,  ///< the weighted mean of a pigment_map's pigments
    Layered,  ///< two entries: a texture layer (the second) over the one below (the first)
    ImageMap,  ///< an image_map: PigmentTable::images[node.image]
    DensityFile,  ///< density_file df3: a DF3 grid over the unit cube (pattern/density_file.h)
    ImagePattern,  ///< image_pattern: the grey of PigmentTable::images[node.image] (ImageMap::value)
    Object,  ///< object: a list of two, outside and inside an object (pattern/object_pattern.h)
    Tiling,    ///< tiling N: one of 27 bevelled tilings of the x-z plane (pattern/tiling.h)
    Pavement,  ///< pavement: the x-z plane paved with one polyform (pattern/pavement.h)
    MaterialMap,   ///< material_map: the texel's index in PigmentTable::images[node.image] picks the entry
};

/// True for checker, hexagon, brick, square, triangular, cubic and object (a list of 2 to 6
/// colours, no wave, no map).
constexpr bool isBlockPattern(PatternKind k) {
    return (k >= PatternKind::Checker && k <= PatternKind::Cubic) || k == PatternKind::Object;
}

/// The modifiers some patterns read.
struct PatternParams {
    Vec3 vector{1, 0, 0};          ///< gradient's direction, normalised
    Vec3 brickSize{8, 3, 4.5};     ///< brick_size
    double mortar = 0.5;           ///< mortar
    double agateTurb = 1;          ///< agate_turb
    Turbulence turbulence;         ///< turbulence, octaves, omega, lambda
    int iterations = 0, exponent = 2;  ///< mandel, julia
    double juliaR = 0, juliaI = 0;     ///< julia's (and magnet julia's) complex constant c
    int magnetFormula = 1;             ///< magnet 1 or 2
    bool magnetJulia = false;          ///< magnet's julia type (z starts at the point, c fixed)
    double arms = 1;                   ///< spiral1's and spiral2's number of arms (an integer)
    int exterior = 1, interior = 0;    ///< mandel's colouring types (0..8, 0..6)
    double exteriorFactor = 1, interiorFactor = 1;
    Slope slope;                       ///< Slope's direction, altitude and ranges
    Quilt quilt;                       ///< quilted's control0 and control1
    int source = -1;                   ///< PigmentPattern: the pigment's node in the same table
    const fn::Program* function = nullptr;  ///< Function: the program (kept alive by the PigmentTable)
    const DensityGrid* grid = nullptr;      ///< DensityFile: the grid (kept alive by the PigmentTable)
    int interpolate = 0;                    ///< DensityFile: 0 nearest, 1 trilinear, 2 tricubic
    const PatternObject* object = nullptr;  ///< Object: the inside test (kept alive by the PigmentTable)
    int tiling = 1;                         ///< Tiling: the tiling's number (1 to 27)
    Pavement pavement;                      ///< Pavement: its tile and corners
    Crackle crackle;                        ///< Crackle: form, metric, offset, solid
    /// noise_generator: 1, 2 or 3; 0 until the scene's global setting (default 2) is filled in.
    int noiseGenerator = 0;
    /// number_of_waves (ripples, waves): 1 to kMaxWaves; 0 until the scene's global setting
    /// (default 10) is filled in, and taken as 10 if never.
    int waves = 0;
};

/// The value an escape-time fractal (mandel, julia, magnet) gives its point: from the exterior type
/// when the orbit escaped after n + 1 new points (n counted from 0), else from the interior type;
/// (zr, zi) the last point, minAbs2 the smallest |z|² of the orbit.
double escapeColouring(const PatternParams& m, bool escaped, int n, double zr, double zi, double minAbs2);

/// The value of a continuous pattern at p (pattern space), turbulence included, before the wave.
/// N: the world normal facing the viewer at the surface point (slope and aoi read it), D: the
/// direction of the ray that met the surface (aoi); zero where there is no surface.
double patternValue(PatternKind kind, const PatternParams& params, Vec3 p, Vec3 N = {}, Vec3 D = {});
/// The list index (0 to 5) of a block pattern at p, turbulence included.
int blockIndex(PatternKind kind, const PatternParams& params, Vec3 p);

}  // namespace rays::pattern
