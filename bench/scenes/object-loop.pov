// Parse benchmark: 100,000 spheres made in a #for loop from rand(), each with its own pigment and
// finish (bench/parse_speed.sh bench/scenes/object-loop.pov). Written for Rays' benchmarks.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare R = seed(1);
#for (J, 1, 100000)
  sphere { <rand(R), rand(R), rand(R)> * 10, 0.1 pigment { rgb <rand(R), 0.5, 0.5> } finish { phong 0.5 } }
#end
camera { location <5, 5, -20> look_at <5, 5, 5> }
light_source { <0, 20, -20> rgb 1 }
