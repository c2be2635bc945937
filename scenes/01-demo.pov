// Demo: every course-dialect shape, transforms, reflection, refraction and shadows.
// Render: rays render scenes/01-demo.pov 800 600 -fresnel -beers -ss=2 -o demo.png

camera {
  location  <0, 3, 16>
  up        <0, 1, 0>
  right     <1.33333, 0, 0>
  look_at   <0, 0.5, 0>
}

light_source { <-20, 30, 25> color rgb <1.2, 1.2, 1.2> }
light_source { <25, 15, 10>  color rgb <0.4, 0.4, 0.5> }

// Floor: a slightly reflective plane.
plane { <0, 1, 0>, -2
  pigment { color rgb <0.75, 0.72, 0.65> }
  finish { ambient 0.15 diffuse 0.7 reflection 0.25 }
}

// Back wall.
plane { <0, 0, 1>, -30
  pigment { color rgb <0.25, 0.35, 0.55> }
  finish { ambient 0.3 diffuse 0.6 }
}

// Glass sphere (refraction with Fresnel and Beer's law when enabled).
sphere { <0, 0.5, 2>, 2.5
  pigment { color rgbf <0.85, 0.95, 1.0, 0.85> }
  finish { ambient 0.05 diffuse 0.1 specular 0.8 roughness 0.05 ior 1.5 }
}

// Mirror sphere.
sphere { <-6, 0.5, -4>, 2.5
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.05 diffuse 0.2 specular 0.6 roughness 0.05 reflection 0.8 }
}

// Red ellipsoid: a sphere under non-uniform scale and rotation.
sphere { <0, 0, 0>, 1
  pigment { color rgb <0.9, 0.15, 0.1> }
  finish { ambient 0.15 diffuse 0.7 specular 0.5 roughness 0.15 }
  scale <2.2, 0.9, 0.9>
  rotate <0, 0, 30>
  translate <6, 0.6, -3>
}

// Rotated box.
box { <-1.2, -1.2, -1.2>, <1.2, 1.2, 1.2>
  pigment { color rgb <0.2, 0.7, 0.3> }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 roughness 0.3 }
  rotate <0, 35, 0>
  translate <3.5, -0.8, 4>
}

// Cone with caps.
cone { <0, -2, 0>, 1.4, <0, 1.6, 0>, 0
  pigment { color rgb <0.95, 0.75, 0.15> }
  finish { ambient 0.15 diffuse 0.7 specular 0.4 roughness 0.2 }
  translate <-3.2, 0, 5>
}

// A triangle standing on the floor.
triangle { <-12, -2, -12>, <-7, -2, -14>, <-9.5, 5, -13>
  pigment { color rgb <0.6, 0.3, 0.8> }
  finish { ambient 0.2 diffuse 0.7 }
}
