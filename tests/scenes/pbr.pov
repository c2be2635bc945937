// Golden test: Cook-Torrance with roughness and ior variations (render with --shading cook-torrance).
camera { location <0, 0, 10> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }
light_source { <-10, 10, 10> color rgb <1.0, 0.8, 0.8> }
light_source { <10, 10, 10> color rgb <0.3, 0.5, 1.0> }
sphere { <-3, 0, 0>, 1.2 pigment { color rgb 1 } finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.1 ior 1.5 } }
sphere { <0, 0, 0>, 1.2 pigment { color rgb 1 } finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.3 ior 2.0 } }
sphere { <3, 0, 0>, 1.2 pigment { color rgb <1, 0.8, 0.4> } finish { ambient 0.1 diffuse 0.5 specular 0.8 roughness 0.4 ior 1.5 metallic 1 } }
plane { <0, 1, 0>, -1.2 pigment { color rgb <0.4, 0.4, 0.4> } finish { ambient 0.2 diffuse 0.6 } }
