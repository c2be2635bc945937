// Golden test: refraction, reflection and total internal reflection (render with -fresnel -beers).
camera { location <0, 1, 10> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }
light_source { <-8, 10, 10> color rgb <1.3, 1.3, 1.3> }
plane { <0, 1, 0>, -2 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.3 diffuse 0.6 reflection 0.3 } }
plane { <0, 0, 1>, -8 pigment { color rgb <0.2, 0.5, 0.8> } finish { ambient 0.4 diffuse 0.6 } }
sphere { <-1.8, 0, 0>, 1.6 pigment { color rgbf <0.6, 1.0, 0.6, 0.9> } finish { ambient 0.05 diffuse 0.1 specular 0.5 roughness 0.05 ior 1.5 } }
sphere { <1.8, 0, 0>, 1.6 pigment { color rgb <1, 0.9, 0.8> } finish { ambient 0.1 diffuse 0.3 reflection 0.7 } }
box { <-0.6, -2, -4>, <0.6, 0.5, -3> pigment { color rgb <0.9, 0.2, 0.2> } finish { ambient 0.3 diffuse 0.6 } }
