// Refraction: glass spheres with Fresnel and Beer's law in front of a checker of boxes.
// rays render --scene refraction -fresnel -beers --spp 4
camera {
  location <0, 2.5, 11>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 0.5, 0>
}

light_source { <-6, 12, 10> color rgb <1.3, 1.3, 1.3> }

plane { <0, 1, 0>, -1 pigment { color rgb <0.9, 0.88, 0.8> } finish { ambient 0.25 diffuse 0.7 } }
box { <-6, -1, -4>, <-4, 3, -3> pigment { color rgb <0.9, 0.2, 0.2> } finish { ambient 0.3 diffuse 0.6 } }
box { <-2, -1, -4>, <0, 3, -3> pigment { color rgb <0.2, 0.8, 0.3> } finish { ambient 0.3 diffuse 0.6 } }
box { <2, -1, -4>, <4, 3, -3> pigment { color rgb <0.2, 0.3, 0.9> } finish { ambient 0.3 diffuse 0.6 } }

sphere { <-2.6, 0.6, 1>, 1.6
  pigment { color rgbf <1, 1, 1, 0.95> }
  finish { ambient 0.02 diffuse 0.05 specular 0.8 roughness 0.04 ior 1.5 } }
sphere { <0.8, 0.3, 1.8>, 1.3
  pigment { color rgbf <0.6, 0.85, 1.0, 0.9> }
  finish { ambient 0.02 diffuse 0.05 specular 0.8 roughness 0.04 ior 1.33 } }
sphere { <3.6, 0.6, 0.6>, 1.6
  pigment { color rgbf <1.0, 0.7, 0.4, 0.9> }
  finish { ambient 0.02 diffuse 0.05 specular 0.8 roughness 0.04 ior 2.4 } }
