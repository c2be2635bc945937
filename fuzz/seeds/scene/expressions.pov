// Expressions, directives, comments and unsupported keywords.
#version 3.7;
#declare R = 2;
#include "colors.inc"
/* block
   comment */
global_settings { assumed_gamma 1.0 }
camera { location <0, 2*2, -(3+4)> up y right 4/3*x look_at <0,0,0> }
light_source { <-10, 10, 10>, color rgb <1.5, 1.5, 1.5> }
light_source { <20, 30, 10> color rgb 1 parallel point_at <0, 0, 0> }
sphere { <0,0,0>, 1.5 pigment { color rgbf <1, .5, 0.25, 0.5> } finish { ambient .2, diffuse 0.5 phong 1 } scale <1,2,1> rotate 30*y translate -x }
plane { <0,1,0>, -1 pigment { rgb <.8,.8,.8> } finish { reflection 0.3 } }
triangle { <0,0,0>, <1,0,0>, <0,1,0> pigment { color rgbt <1,1,1,0.2> } }
box { <-1,-1,-1>, <1,1,1> matrix <1,0,0, 0,1,0, 0,0,1, 2,0,0> texture { pigment { color rgb 1 } finish { specular 0.5 roughness 0.05 metallic } } }
cone { <0,0,0>, 1, <0,2,0>, 0 interior { ior 1.33 } pigment { color rgbft <1,1,1,0.5,0.1> } }
torus { 1, 0.2 }
