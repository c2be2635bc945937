// Edge-guided anti-aliasing: thin bars and shadow edges; supersample only where ids or shadows change.
// rays render --scene edge-aa --aa-edges --spp 16
camera {
  location <0, 2, 12>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 1, 0>
}

light_source { <6, 12, 8> color rgb <1.2, 1.2, 1.2> }

plane { <0, 1, 0>, -1 pigment { color rgb <0.95, 0.95, 0.95> } finish { ambient 0.2 diffuse 0.7 } }
plane { <0, 0, 1>, -6 pigment { color rgb <0.15, 0.2, 0.35> } finish { ambient 0.4 diffuse 0.5 } }

box { <-5, -1, -0.1>, <-4.8, 4, 0.1> rotate <0, 0, -12> pigment { color rgb <0.1, 0.1, 0.1> } finish { ambient 0.3 diffuse 0.6 } }
box { <-3.5, -1, -0.1>, <-3.35, 4, 0.1> rotate <0, 0, -9> pigment { color rgb <0.1, 0.1, 0.1> } finish { ambient 0.3 diffuse 0.6 } }
box { <-2, -1, -0.1>, <-1.9, 4, 0.1> rotate <0, 0, -6> pigment { color rgb <0.1, 0.1, 0.1> } finish { ambient 0.3 diffuse 0.6 } }
sphere { <2, 1, 0>, 2 pigment { color rgb <0.9, 0.3, 0.1> } finish { ambient 0.2 diffuse 0.7 specular 0.6 roughness 0.08 } }
triangle { <-1, -1, 3>, <1.5, -1, 2.5>, <0, 2.5, 1> pigment { color rgb <0.2, 0.7, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
