camera { location <0,1,12> up <0,1,0> right <1.33333,0,0> look_at <0,1,0> aperture 0.25 focal_point <0,1,5> blur_samples 4, 32 }
camera { location <0,1,-12> up <0,1,0> right <1.33333,0,0> look_at <0,1,0> }
light_source { <0,10,0> color rgb 1 area_light <2,0,0>, <0,0,2>, 8, 8 jitter adaptive 1 circular orient }
edges { silhouette, crease occlusion intersection material shadow reflection edge_method image edge_width 2 edge_color rgb <0.1,0.1,0.4> crease_angle 45 lines_only }
edges { all edge_method stencil }
sphere { <0,1,0>, 1 finish { ambient 0.1 diffuse 0.6 specular 0.4 roughness 0.1 reflection 0.5 refraction 1 ior 1.5 sigma 20 } shading lambert }
