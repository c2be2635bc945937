camera { location <0,1,12> up <0,1,0> right <1.33333,0,0> look_at <0,1,0> aperture 0.25 focal_point <0,1,5> blur_samples 4, 32 }
camera { location <0,1,-12> up <0,1,0> right <1.33333,0,0> look_at <0,1,0> }
light_source { <0,10,0> color rgb 1 area_light <2,0,0>, <0,0,2>, 8, 8 jitter adaptive 177777777777777777777777777777777777777777777777 circular orient te, crease oefraction 1 ior 1.5 sigma 20 } shading lambert }
