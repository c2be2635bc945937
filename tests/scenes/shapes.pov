// Golden test: every shape, transforms in mixed order, two lights, shadows.
camera { location <0, 2, 12> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }
light_source { <-10, 12, 10> color rgb <1, 1, 1> }
light_source { <8, 6, 12> color rgb <0.3, 0.3, 0.4> }
plane { <0, 1, 0>, -2 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <0, 0, 0>, 1 scale <1.5, 0.7, 0.7> rotate <0, 0, 30> translate <-3.5, 0, 0>
  pigment { color rgb <0.9, 0.2, 0.1> } finish { ambient 0.2 diffuse 0.6 specular 0.6 roughness 0.1 } }
box { <-1, -1, -1>, <1, 1, 1> translate <0, -1, 0> rotate <0, 40, 0> scale 0.9
  pigment { color rgb <0.2, 0.8, 0.3> } finish { ambient 0.2 diffuse 0.7 } }
cone { <0, -2, 0>, 1, <0, 1.5, 0>, 0.2 rotate <20, 0, 0> translate <3.5, 0, 0>
  pigment { color rgb <0.9, 0.8, 0.1> } finish { ambient 0.2 diffuse 0.7 specular 0.3 roughness 0.3 } }
triangle { <-6, -2, -4>, <6, -2, -4>, <0, 5, -5>
  pigment { color rgb <0.3, 0.4, 0.9> } finish { ambient 0.3 diffuse 0.6 } }
