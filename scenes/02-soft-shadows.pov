// Soft shadows: a 2x2 area light with 8x8 jittered samples over spheres, a box and a cone.
// rays render --scene soft-shadows --spp 16
camera {
  location <0, 4, 13>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 0.5, 0>
}

light_source { <-4, 10, 6> color rgb <1.3, 1.25, 1.2>
  area_light <2.5, 0, 0>, <0, 0, 2.5>, 8, 8
  jitter
}

plane { <0, 1, 0>, -1 pigment { color rgb <0.85, 0.85, 0.8> } finish { ambient 0.15 diffuse 0.8 } }

sphere { <-3, 0.5, 0>, 1.5
  pigment { color rgb <0.9, 0.25, 0.2> }
  finish { ambient 0.15 diffuse 0.7 specular 0.5 roughness 0.1 } }
sphere { <0.5, 0, 2>, 1
  pigment { color rgb <0.2, 0.5, 0.9> }
  finish { ambient 0.15 diffuse 0.7 specular 0.5 roughness 0.1 } }
box { <-1, -1, -1>, <1, 1, 1> rotate <0, 30, 0> translate <3.2, 0, -1>
  pigment { color rgb <0.3, 0.8, 0.35> } finish { ambient 0.15 diffuse 0.7 } }
cone { <0, -1, 0>, 0.9, <0, 2.5, 0>, 0 translate <-0.5, 0, -3>
  pigment { color rgb <0.95, 0.8, 0.2> } finish { ambient 0.15 diffuse 0.7 specular 0.3 roughness 0.2 } }
