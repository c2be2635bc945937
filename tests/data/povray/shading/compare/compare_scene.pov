#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0,1.2,-5> look_at <0,1.2,0> right x*4/3 up y }
background { rgb <0.2,0.3,0.5> }
light_source { <-3,5,-4>, rgb 1.2 }
light_source { <3,4,-2>, rgb <0.3,0.25,0.2> parallel point_at <0,0,0> }
plane { y, 0 pigment { rgb <0.8,0.7,0.6> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-0.6,1,0>, 1 pigment { rgbf <0.9,1,0.9,0.9> } finish { ambient 0 diffuse 0.1 phong 1 phong_size 80 reflection { 0.05, 1 fresnel on } conserve_energy }
  interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color <0.5,0.8,0.6> } }
sphere { <1.5,0.7,2>, 0.7 pigment { rgb <0.9,0.2,0.1> } finish { ambient 0.1 diffuse 0.6 specular 0.6 roughness 0.02 metallic reflection { 0.2 metallic 1 } } }
box { <1.2,0,-1.5>, <2.2,0.8,-1.4> pigment { rgbt <0.2,0.4,1,0.6> } finish { ambient 0.2 diffuse 0.5 phong 0.5 } }
sphere { <-2.2,0.5,1.5>, 0.5 pigment { rgb <0.3,0.9,0.3> } finish { ambient 0.1 diffuse 0.6, 0.3 brilliance 2 phong 0.4 phong_size 20 } }
