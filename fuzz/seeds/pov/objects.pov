// Every object keyword with its modifiers.
#include "colors.inc"
camera { perspective location <0, 3, -10> look_at 0 angle 60 right x * 4/3 up y sky y }
light_source { <10, 10, -10> color White }
light_source { <0, 10, 0> color rgb 0.5 spotlight point_at 0 radius 10 falloff 20 tightness 5 }
light_source { <-5, 5, -5> rgb 1 area_light x, z, 4, 4 adaptive 1 jitter circular orient }
light_source { <0, 0, -10> rgb 1 parallel point_at 0 shadowless }
sphere { 0, 1 texture { Plain } }
box { -1, 1 rotate <10, 20, 30> scale 0.5 translate x hollow no_shadow }
cone { 0, 1, y, 0.5 open }
cylinder { 0, y, 0.5 }
plane { y, -2 pigment { checker White Black } }
torus { 1, 0.2 sturm }
disc { 0, y, 1, 0.2 }
polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }
prism { linear_sweep linear_spline 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
lathe { cubic_spline 5, <0, 0>, <1, 0>, <1, 1>, <0.5, 2>, <0, 2> }
sor { 4, <0, 0>, <1, 0>, <1, 1>, <0, 2> }
superellipsoid { <0.5, 0.5> }
blob { threshold 0.5 sphere { 0, 1, 1 } cylinder { 0, x, 0.5, 1 } component 1, 1, <0, 1, 0> }
height_field { function 16, 16 { x * y } smooth water_level 0.1 }
text { ttf "crystal.ttf" "abc" 0.2, <0.1, 0> }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1> }
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1> }
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }
polynomial { 2, xyz(2, 0, 0): 1, xyz(0, 2, 0): 1, xyz(0, 0, 2): 1, xyz(0, 0, 0): -1 }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }
bicubic_patch { type 1 flatness 0.1 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>, <0, 1, 0>, <1, 1, 1>, <2, 1, 1>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 1>, <2, 2, 1>, <3, 2, 0>, <0, 3, 0>, <1, 3, 0>, <2, 3, 0>, <3, 3, 0> }
ovus { 1, 0.5 }
mesh { triangle { 0, x, y } smooth_triangle { 0, y, x, y, y, z } inside_vector z }
mesh2 { vertex_vectors { 3, 0, x, y } normal_vectors { 1, z } uv_vectors { 3, <0, 0>, <1, 0>, <0, 1> }
  texture_list { 1, texture { pigment { Red } } } face_indices { 1, <0, 1, 2>, 0 } normal_indices { 1, <0, 0, 0> } uv_indices { 1, <0, 1, 2> } }
union { sphere { 0, 1 } box { 0, 1 } split_union off }
intersection { sphere { 0, 1 } box { 0, 1 } inverse }
difference { sphere { 0, 1 } box { 0, 1 } cutaway_textures }
merge { sphere { 0, 1 } sphere { x, 1 } }
object { sphere { 0, 1 } bounded_by { box { -1, 1 } } clipped_by { plane { y, 0 } } }
light_group { light_source { 0, rgb 1 } sphere { 0, 1 } global_lights on }
#declare T = transform { rotate 45 * y scale 2 translate -x };
sphere { 0, 1 transform { T inverse } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> }
background { color rgb <0.1, 0.2, 0.3> }
fog { fog_type 2 distance 10 color rgb 0.5 fog_offset 0 fog_alt 1 turbulence 0.2 }
sky_sphere { pigment { gradient y color_map { [0 White] [1 Blue] } } }
rainbow { angle 42.5 width 5 distance 1000 direction <-0.2, -0.2, 1> jitter 0.01 arc_angle 180 falloff_angle 30
  color_map { [0 rgbt <1, 0, 0, 0.5>] [1 rgbt <0, 0, 1, 0.5>] } }
global_settings { assumed_gamma 1.0 max_trace_level 10 ambient_light rgb 0.2 charset utf8
  radiosity { count 50 error_bound 1 recursion_limit 2 } photons { spacing 0.1 } }
