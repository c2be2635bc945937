// Pigment functions measured with POV-Ray 3.7.0.10 (the values in pigment_functions.txt):
//   povray +Ipigment_functions.pov -D +W8 +H8 -O/dev/null 2>&1 | grep -oE 'PIG.*' > pigment_functions.txt
// (#debug lines wrap at 80 columns: three values per line.) tests/pov_pattern_function_test.cpp
// runs this file through Rays and compares.
#version 3.7;
#declare P = array[6] { <0.3,0.2,0.1>, <1.7,-0.4,2.2>, <-0.35,0.8,-1.6>, <2.25,1.5,0.5>, <-1.2,-2.7,0.45>, <0.05,0.6,-0.3> }
#macro Show(Name, F)
  #local i = 0;
  #while (i < 6)
    #local c = F(P[i].x,P[i].y,P[i].z);
    #local g = F(P[i].x,P[i].y,P[i].z).gray;
    #debug concat("PIG ", Name, " ", str(i,0,0), " ", str(c.red,0,12), " ", str(c.green,0,12), " ", str(c.blue,0,12), "\n")
    #debug concat("PIG2 ", Name, " ", str(i,0,0), " ", str(c.filter,0,12), " ", str(c.transmit,0,12), " ", str(g,0,12), "\n")
    #local i = i + 1;
  #end
#end
#declare F1 = function { pigment { gradient x color_map { [0 rgbf <1,0,0,0.5>] [1 rgbt <0,0.5,1,0.25>] } } } Show("gradient_map", F1)
#declare F2 = function { pigment { checker rgb <1,0.5,0.25> rgbft <0,0.2,0.4,0.6,0.8> } } Show("checker", F2)
#declare F3 = function { pigment { rgb <0.1,0.2,0.3> } } Show("flat", F3)
#declare F4 = function { pigment { gradient y } } Show("gradient_nomap", F4)
#declare F5 = function { pigment { onion color_map { [0 rgb 0] [0.5 rgb <1,0,0>] [1 rgb 1] } scale 2 translate x } } Show("onion_moved", F5)
#declare F6 = function { pigment { checker pigment { gradient x } pigment { rgb <0,0,1> } } } Show("checker_pigments", F6)
#declare F7 = function { pigment { wood } } Show("wood_default", F7)
#declare F8 = function { pigment { hexagon } } Show("hexagon_default", F8)
#declare F9 = function { pigment { radial frequency 3 color_map { [0 rgb x] [1 rgb y] } } } Show("radial_freq", F9)

#declare H = function(a,b,c) { F1(a,b,c).red + 10*F2(a,b,c).transmit + 100*F5(a,b,c).gray }
#declare i = 0;
#while (i < 6)
  #debug concat("PIGFN combined ", str(i,0,0), " ", str(H(P[i].x,P[i].y,P[i].z),0,12), "\n")
  #declare i = i + 1;
#end
