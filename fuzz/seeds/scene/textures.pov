camera { location <0,3,10> up <0,1,0> right <1.33333,0,0> look_at <0,0.8,0> }
light_source { <-6,8,8> color rgb <1.2,1.2,1.2> }
plane { <0,1,0>, -1 pigment { image_map { png "tex.png" interpolate 2 once gamma 2.2 } rotate <90,0,0> scale 4 } }
sphere { <0,0,0>, 1 pigment { image_map { "tex.png" map_type 1 } } normal { normal_map { png "tex.png" map_type 2 strength 1.5 } scale 2 } }
sphere { <2,0,0>, 1 normal { bump_map { png "tex.png" map_type 1 bump_size 1 } } uv_mapping }
