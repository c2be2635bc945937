// Object patterns measured with POV-Ray 3.7.0.10 (the values in object_patterns.txt):
//   povray +Iobject_patterns.pov -D +W8 +H8 -O/dev/null 2>&1 | grep -oE 'OBJ.*' > object_patterns.txt
// Each line: the pattern function's value (0 outside, 1 inside) at 4 points. The points are
// random in [-2, 2]^3. tests/pov_pattern_function_test.cpp runs this file through Rays and compares.
#version 3.7;
#declare R = seed(7);
#declare N = 40;
#declare P = array[N]
#for (i, 0, N - 1) #declare P[i] = <rand(R), rand(R), rand(R)> * 4 - 2; #end
#macro Show(Name, O)
  #local F = function { pattern { object { O } } }
  #for (i, 0, N - 1, 4)
    #debug concat("OBJ ", Name, " ", str(i,0,0), " ", str(F(P[i].x,P[i].y,P[i].z),0,0), " ", str(F(P[i+1].x,P[i+1].y,P[i+1].z),0,0), " ", str(F(P[i+2].x,P[i+2].y,P[i+2].z),0,0), " ", str(F(P[i+3].x,P[i+3].y,P[i+3].z),0,0), "\n")
  #end
#end
Show("sphere", sphere { <0.2, -0.1, 0.3>, 1.3 })
Show("box", box { <-1, -0.5, -1.5>, <1.5, 1, 0.5> rotate <20, 30, 40> })
Show("cylinder", cylinder { <-1, -1, 0>, <1, 1.5, 0.5>, 0.8 })
Show("cone", cone { <0, -1.5, 0>, 1.4, <0, 1.5, 0.3>, 0.2 })
Show("torus", torus { 1.2, 0.5 rotate x*30 })
Show("plane", plane { <1, 1, 0.5>, 0.3 })
Show("difference", difference { box { -1.5, 1.5 } sphere { 0, 1.7 } })
Show("intersection", intersection { sphere { <-0.5, 0, 0>, 1.5 } sphere { <0.5, 0, 0>, 1.5 } cylinder { -2*z, 2*z, 1 } })
Show("merge", merge { sphere { <-1, 0, 0>, 1 } box { <0, -0.5, -0.5>, <2, 0.5, 0.5> } })
Show("union", union { sphere { <1, 1, 0>, 0.9 } sphere { <-1, -1, 0>, 0.9 } translate z*0.5 })
Show("inverse", sphere { 0, 1.5 inverse })
Show("scaled", object { sphere { 0, 1 } scale <1.8, 0.6, 1> rotate z*45 })
Show("superellipsoid", superellipsoid { <0.3, 0.6> scale 1.5 })
Show("quadric", quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.5 })
Show("ovus", ovus { 1, 0.6 })
// Meshes: inside only with an inside_vector (the crossings along it counted); a triangle has none.
#declare A = <-1,-1,-1>; #declare B = <1.5,-1,-1>; #declare C = <0,1.5,-1>; #declare D = <0,0,1.5>;
#for (i, 0, N - 1) #declare P[i] = <rand(R), rand(R), rand(R)> * 2 - 0.8; #end
Show("mesh", mesh { triangle { A, B, C } triangle { A, B, D } triangle { B, C, D } triangle { C, A, D } inside_vector <0.3, 0.2, 1> })
Show("mesh2", mesh2 { vertex_vectors { 4, A, B, C, D } face_indices { 4, <0,1,2>, <0,1,3>, <1,2,3>, <2,0,3> } inside_vector x translate x*0.5 })
Show("mesh_without_inside_vector", mesh { triangle { A, B, C } triangle { A, B, D } triangle { B, C, D } triangle { C, A, D } })
Show("triangle", triangle { A, B, C })
