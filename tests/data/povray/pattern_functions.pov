// Pattern functions measured with POV-Ray 3.7.0.10 (the values in pattern_functions.txt):
//   povray +Ipattern_functions.pov -D +W8 +H8 -O/dev/null 2>&1 | grep -oE 'PAT.*' > pattern_functions.txt
// (#debug lines wrap at 80 columns: one value per line.) tests/pov_pattern_function_test.cpp
// runs this file through Rays and compares.
#version 3.7;
#declare P = array[6] { <0.3,0.2,0.1>, <1.7,-0.4,2.2>, <-0.35,0.8,-1.6>, <2.25,1.5,0.5>, <-1.2,-2.7,0.45>, <0.05,0.6,-0.3> }
#macro Show(Name, F)
  #local i = 0;
  #while (i < 6)
    #debug concat("PAT ", Name, " ", str(i,0,0), " ", str(F(P[i].x,P[i].y,P[i].z),0,12), "\n")
    #local i = i + 1;
  #end
#end
#declare F1 = function { pattern { gradient x } } Show("gradient_x", F1)
#declare F2 = function { pattern { gradient <1,2,0> } } Show("gradient_12", F2)
#declare F3 = function { pattern { gradient x frequency 2 } } Show("gradient_freq2", F3)
#declare F4 = function { pattern { gradient x triangle_wave } } Show("gradient_tri", F4)
#declare F5 = function { pattern { gradient x sine_wave } } Show("gradient_sine", F5)
#declare F6 = function { pattern { gradient x phase 0.3 } } Show("gradient_phase", F6)
#declare F7 = function { pattern { gradient x scale 3 translate 0.5 } } Show("gradient_scaled", F7)
#declare F9 = function { pattern { checker } } Show("checker", F9)
#declare F10 = function { pattern { hexagon } } Show("hexagon", F10)
#declare F11 = function { pattern { brick } } Show("brick", F11)
#declare F12 = function { pattern { onion } } Show("onion", F12)
#declare F13 = function { pattern { spherical } } Show("spherical", F13)
#declare F14 = function { pattern { radial } } Show("radial", F14)
#declare F15 = function { pattern { wood } } Show("wood", F15)
#declare F16 = function { pattern { leopard } } Show("leopard", F16)
#declare F17 = function { pattern { boxed } } Show("boxed", F17)
#declare F18 = function { pattern { cylindrical } } Show("cylindrical", F18)
#declare F19 = function { pattern { planar } } Show("planar", F19)
#declare F20 = function { pattern { gradient x scallop_wave } } Show("gradient_scallop", F20)
#declare F21 = function { pattern { gradient x cubic_wave } } Show("gradient_cubic", F21)
#declare F22 = function { pattern { gradient x poly_wave 2 } } Show("gradient_poly2", F22)
#declare F23 = function { pattern { marble } } Show("marble", F23)
#declare F24 = function { pattern { mandel 20 } } Show("mandel", F24)
#declare F25 = function { pattern { checker scale 0.5 rotate 30*y } } Show("checker_moved", F25)
#declare F26 = function { pattern { function { x*y+z } } } Show("function_xyz", F26)
#declare F27 = function { pattern { gradient y warp { repeat x*0.7 offset <0,0.2,0> } } } Show("gradient_warp", F27)
#declare F28 = function { pattern { gradient x frequency -1 } } Show("gradient_freqm1", F28)
#declare F29 = function { pattern { brick brick_size <1,0.5,0.7> mortar 0.1 } } Show("brick_sized", F29)
#declare G = function(a,b,c) { F1(a,b,c)*2 + F9(c,b,a) } Show("combined", G)
