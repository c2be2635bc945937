// Feature lines in reflections: outlines of objects seen in two mirrors follow the reflected rays.
// rays render --scene mirror-lines --edges all
camera {
  location <0, 3, 9>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 1, 0>
}

light_source { <-5, 10, 8> color rgb <1.2, 1.2, 1.2> }

plane { <0, 1, 0>, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.2 diffuse 0.7 } }
box { <-4, 0, -3.2>, <4, 4, -3> pigment { color rgb <0.85, 0.9, 0.95> } finish { ambient 0.05 diffuse 0.1 reflection 0.85 } }
box { <-4.2, 0, -3>, <-4, 4, 3> pigment { color rgb <0.85, 0.9, 0.95> } finish { ambient 0.05 diffuse 0.1 reflection 0.85 } }

sphere { <-1, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.7 specular 0.5 roughness 0.1 } }
cone { <1.5, 0, 0.5>, 0.8, <1.5, 2.2, 0.5>, 0 pigment { color rgb <0.95, 0.8, 0.2> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate <0, 30, 0> translate <0.5, 0, 2> pigment { color rgb <0.3, 0.7, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
