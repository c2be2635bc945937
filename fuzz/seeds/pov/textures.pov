// Every texture keyword: pigments and patterns, maps, normals, finishes, interiors and media,
// materials, layered textures, tiles and material maps, warps.
#include "colors.inc"
#declare P = pigment { gradient x color_map { [0 Red] [0.5 Green] [1 Blue] } frequency 2 phase 0.1 sine_wave }
sphere { 0, 1 texture { pigment { P } normal { bumps 0.5 scale 0.1 } finish { phong 0.5 phong_size 40 specular 0.3 roughness 0.05 reflection { 0.1, 0.5 fresnel on metallic } ambient 0.1 emission 0 diffuse albedo 0.6 brilliance 1 irid { 0.3 thickness 0.1 turbulence 0.1 } conserve_energy } } }
sphere { x, 1 pigment { agate agate_turb 0.5 } }
sphere { x, 1 pigment { bozo turbulence 0.5 octaves 4 omega 0.5 lambda 2 color_map { [0 White] [1 Black] } } }
sphere { x, 1 pigment { brick Red, White brick_size <1, 0.5, 0.5> mortar 0.1 } }
sphere { x, 1 pigment { cells } normal { dents 0.3 } }
sphere { x, 1 pigment { crackle form <1, 0, 0> metric 2 offset 0 solid } }
sphere { x, 1 pigment { hexagon Red, Green, Blue } }
sphere { x, 1 pigment { granite } normal { wrinkles 0.5 } }
sphere { x, 1 pigment { leopard } normal { ripples 0.5 } }
sphere { x, 1 pigment { mandel 25 exponent 2 } normal { waves 0.5 } }
sphere { x, 1 pigment { julia <0.3, 0.5>, 20 interior 1, 1 exterior 1, 1 } }
sphere { x, 1 pigment { magnet 1 mandel 20 } }
sphere { x, 1 pigment { marble warp { turbulence 0.5 } } }
sphere { x, 1 pigment { onion } normal { facets } }
sphere { x, 1 pigment { pavement number_of_sides 4 number_of_tiles 2 pattern 1 } }
sphere { x, 1 pigment { planar } normal { quilted control0 0.5 control1 0.5 } }
sphere { x, 1 pigment { radial frequency 6 } }
sphere { x, 1 pigment { spherical } }
sphere { x, 1 pigment { spiral1 3 } }
sphere { x, 1 pigment { spiral2 3 } }
sphere { x, 1 pigment { spotted } }
sphere { x, 1 pigment { square Red, Green, Blue, White } }
sphere { x, 1 pigment { tiling 3 } }
sphere { x, 1 pigment { triangular } }
sphere { x, 1 pigment { wood ramp_wave } }
sphere { x, 1 pigment { boxed cubic_wave } }
sphere { x, 1 pigment { cylindrical poly_wave 2 } }
sphere { x, 1 pigment { dents scallop_wave } }
sphere { x, 1 pigment { aoi triangle_wave } }
sphere { x, 1 pigment { average pigment_map { [1 Red] [2 Blue] } } }
sphere { x, 1 pigment { slope { y, 0, 1 } } }
sphere { x, 1 pigment { object { box { 0, 1 } Red, Blue } } }
sphere { x, 1 pigment { pigment_pattern { checker } pigment_map { [0 Red] [1 Blue] } } }
sphere { x, 1 pigment { image_map { png "missing.png" map_type 1 once interpolate 2 filter all 0.5 transmit 1, 0.5 } } }
sphere { x, 1 pigment { function { x } } }
sphere { x, 1 pigment { gradient y warp { repeat x offset y flip x } warp { black_hole 0, 1 falloff 2 strength 1 inverse } warp { cylindrical orientation y dist_exp 1 } warp { planar z, 0 } warp { toroidal major_radius 2 } warp { spherical } } }
sphere { x, 1 normal { bump_map { png "missing.png" bump_size 2 } } }
sphere { x, 1 normal { gradient x normal_map { [0 bumps 0.5] [1 dents 0.5] } } }
sphere { x, 1 normal { granite slope_map { [0 <0, 1>] [1 <1, 0>] } no_bump_scale } }
sphere { x, 1 texture { checker texture { pigment { Red } } texture { pigment { Blue } } } }
sphere { x, 1 texture { gradient x texture_map { [0 pigment { Red }] [1 pigment { Blue }] } } }
sphere { x, 1 texture { pigment { Red } } texture { pigment { rgbt <0, 0, 1, 0.5> } } }
box { 0, 1 texture { tiles { texture { pigment { Red } } tile2 texture { pigment { Blue } } } } }
box { 0, 1 texture { material_map { png "missing.png" texture { pigment { Red } } } } }
sphere { x, 1 pigment { Clear } interior { ior 1.5 caustics 1 dispersion 1.1 dispersion_samples 7 fade_distance 1 fade_power 2 fade_color Red
  media { method 3 intervals 1 samples 2, 4 absorption 0.5 emission 0.1 scattering { 1, 0.5 eccentricity 0.3 extinction 1 }
    density { spherical density_map { [0 rgb 0] [1 rgb 1] } } } } hollow }
sphere { x, 1 material { Glass } }
sphere { x, 1 interior_texture { pigment { Red } } uv_mapping }
sphere { x, 1 finish { subsurface { translucency 0.5 } fresnel on } }
sphere { x, 1 pigment { color red 1 green 0.5 blue 0.25 filter 0.1 transmit 0.2 } }
sphere { x, 1 pigment { srgb <1, 0.5, 0> } }
sphere { x, 1 pigment { rgbf <1, 1, 1, 0.5> quick_color Red } }
