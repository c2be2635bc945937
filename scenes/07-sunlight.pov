// Sunlight: a parallel (directional) light with a soft fill, over a row of columns.
// rays render --scene sunlight --spp 4
camera {
  location <0, 5, 14>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 1, 0>
}

light_source { <20, 30, 10> color rgb <1.1, 1.05, 0.95> parallel point_at <0, 0, 0> }
light_source { <-10, 6, 12> color rgb <0.2, 0.22, 0.3> }

plane { <0, 1, 0>, 0 pigment { color rgb <0.85, 0.8, 0.7> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.4, 0, -0.4>, <0.4, 4, 0.4> translate <-6, 0, 0> pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.4, 0, -0.4>, <0.4, 4, 0.4> translate <-3, 0, 0> pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.4, 0, -0.4>, <0.4, 4, 0.4> translate <0, 0, 0> pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.4, 0, -0.4>, <0.4, 4, 0.4> translate <3, 0, 0> pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.4, 0, -0.4>, <0.4, 4, 0.4> translate <6, 0, 0> pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <0, 1.2, 4>, 1.2 pigment { color rgb <0.8, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.7 specular 0.6 roughness 0.1 } }
