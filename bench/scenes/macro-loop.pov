// Parse benchmark: a macro called 200,000 times from a #while loop, and 20,000 objects made in
// a #for loop from rand() (bench/parse_speed.sh). Written for Rays' benchmarks.
#version 3.7;
global_settings { assumed_gamma 1 }
#macro F(A, B) (A * B + sin(A)) #end
#declare S = 0;
#declare I = 0;
#while (I < 200000)
  #declare S = S + F(I, 2);
  #declare I = I + 1;
#end
#declare R = seed(1);
#for (J, 1, 20000)
  sphere { <rand(R), rand(R), rand(R)> * 10, 0.1 pigment { rgb <rand(R), 0.5, 0.5> } finish { phong 0.5 } }
#end
camera { location <5, 5, -20> look_at <5, 5, 5> }
light_source { <0, 20, -20> rgb 1 }
