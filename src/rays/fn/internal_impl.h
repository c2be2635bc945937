// The internal functions' code. RAYS_FN_INTERNAL_LIST gives each functions.inc name its
// internal number and parameter count (x, y, z included) and declares its f_NAME below;
// internal_functions.cpp builds the numbered table from the same list. Each reads p[0..2] =
// x, y, z and p[3..] = its parameters. Files by family: internal_basic.cpp (distance-like
// shapes), internal_algebraic.cpp (polynomial surfaces with a field strength),
// internal_curves.cpp (the 2-D curves swept or extruded), internal_blobs.cpp (blobs,
// crossed/intersected ellipsoids, flange cover, spikes), internal_helix.cpp (helixes, spiral,
// helical torus), internal_patterns.cpp (2-D spikes, hexagons, mesh, quantum, comma),
// internal_tubes.cpp (poly4, polytubes), internal_noise.cpp (noise and fractal noise).
#pragma once

namespace rays::fn::internal {

#define RAYS_FN_INTERNAL_LIST(X)                                                                   \
    X(0, algbr_cyl1, 8) X(1, algbr_cyl2, 8) X(2, algbr_cyl3, 8) X(3, algbr_cyl4, 8) X(4, bicorn, 5)  \
    X(5, bifolia, 5) X(6, blob, 8) X(7, blob2, 7) X(8, boy_surface, 5) X(9, comma, 4)                \
    X(10, cross_ellipsoids, 7) X(11, crossed_trough, 4) X(12, cubic_saddle, 4) X(13, cushion, 4)     \
    X(14, devils_curve, 4) X(15, devils_curve_2d, 9) X(16, dupin_cyclid, 9) X(17, ellipsoid, 6)     \
    X(18, enneper, 4) X(19, flange_cover, 7) X(20, folium_surface, 6) X(21, folium_surface_2d, 9)   \
    X(22, glob, 4) X(23, heart, 4) X(24, helical_torus, 13) X(25, helix1, 10) X(26, helix2, 10)     \
    X(27, hex_x, 4) X(28, hex_y, 4) X(29, hetero_mf, 9) X(30, hunt_surface, 4)                       \
    X(31, hyperbolic_torus, 6) X(32, isect_ellipsoids, 7) X(33, kampyle_of_eudoxus, 6)              \
    X(34, kampyle_of_eudoxus_2d, 9) X(35, klein_bottle, 4) X(36, kummer_surface_v1, 4)              \
    X(37, kummer_surface_v2, 7) X(38, lemniscate_of_gerono, 4) X(39, lemniscate_of_gerono_2d, 9)    \
    X(40, mesh1, 8) X(41, mitre, 4) X(42, nodal_cubic, 4) X(43, odd, 4) X(44, ovals_of_cassini, 7)  \
    X(45, paraboloid, 4) X(46, parabolic_torus, 6) X(47, ph, 3) X(48, pillow, 4) X(49, piriform, 4) \
    X(50, piriform_2d, 10) X(51, poly4, 8) X(52, polytubes, 9) X(53, quantum, 4)                     \
    X(54, quartic_paraboloid, 4) X(55, quartic_saddle, 4) X(56, quartic_cylinder, 6) X(57, r, 3)    \
    X(58, ridge, 9) X(59, ridged_mf, 9) X(60, rounded_box, 7) X(61, sphere, 4) X(62, spikes, 8)     \
    X(63, spikes_2d, 7) X(64, spiral, 9) X(65, steiners_roman, 4) X(66, strophoid, 7)                \
    X(67, strophoid_2d, 10) X(68, superellipsoid, 5) X(69, th, 3) X(70, torus, 5) X(71, torus2, 6)  \
    X(72, torus_gumdrop, 4) X(73, umbrella, 4) X(74, witch_of_agnesi, 5)                             \
    X(75, witch_of_agnesi_2d, 9) X(76, noise3d, 3) X(78, noise_generator, 4)

#define RAYS_FN_DECLARE_INTERNAL(number, name, params) double f_##name(const double* p);
RAYS_FN_INTERNAL_LIST(RAYS_FN_DECLARE_INTERNAL)
#undef RAYS_FN_DECLARE_INTERNAL

}  // namespace rays::fn::internal
