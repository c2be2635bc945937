// Shadow-boundary lines: two lights cast crossing shadows; their outlines are drawn.
// rays render --scene shadow-lines --edges silhouette,shadow --edge-color 0.1,0.1,0.4
camera {
  location <0, 7, 9>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 0, 0>
}

light_source { <-6, 8, 4> color rgb <0.8, 0.8, 0.8> }
light_source { <5, 6, 2> color rgb <0.5, 0.45, 0.4> }

plane { <0, 1, 0>, 0 pigment { color rgb <0.95, 0.95, 0.9> } finish { ambient 0.25 diffuse 0.7 } }
sphere { <-1, 1, 0>, 1 pigment { color rgb <0.9, 0.4, 0.3> } finish { ambient 0.2 diffuse 0.7 } }
box { <-0.5, 0, -0.5>, <0.5, 2, 0.5> rotate <0, 20, 0> translate <1.5, 0, -0.5> pigment { color rgb <0.4, 0.6, 0.9> } finish { ambient 0.2 diffuse 0.7 } }
cone { <0, 0, 0>, 0.6, <0, 1.8, 0>, 0 translate <0.3, 0, 1.8> pigment { color rgb <0.5, 0.8, 0.4> } finish { ambient 0.2 diffuse 0.7 } }
