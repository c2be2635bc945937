// Textures: image maps (planar, spherical, cylindrical), a brick normal map and a bump map.
// rays render --scene textures --spp 4   (textures made by `rays assets scenes/textures`)
camera {
  location <0, 3, 10>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 0.8, 0>
}

light_source { <-6, 8, 8> color rgb <1.2, 1.2, 1.2> }
light_source { <8, 3, 6> color rgb <0.3, 0.3, 0.35> }

// Checker floor: the planar map lies in x-y, so it is turned onto the floor and enlarged.
plane { <0, 1, 0>, -1
  pigment { image_map { png "textures/checker.png" interpolate 2 } rotate <90, 0, 0> scale 4 }
  finish { ambient 0.25 diffuse 0.7 }
}

// Brick sphere: spherical colour map and the matching tangent-space normal map.
sphere { <-2.6, 0.4, 0>, 1.4
  pigment { image_map { png "textures/bricks.png" map_type 1 interpolate 2 } }
  normal { normal_map { png "textures/bricks-normal.png" map_type 1 strength 1.5 } }
  finish { ambient 0.2 diffuse 0.8 specular 0.3 roughness 0.3 }
}

// Bump-mapped white sphere (the same bricks as a height map).
sphere { <0.4, 0.4, 0.8>, 1.4
  pigment { color rgb <0.9, 0.9, 0.88> }
  normal { bump_map { png "textures/bricks-height.png" map_type 1 bump_size 1 } }
  finish { ambient 0.2 diffuse 0.8 specular 0.4 roughness 0.2 }
}

// Cylindrical map on a box-like pillar: bricks wrapped around.
sphere { <0, 0, 0>, 1
  pigment { image_map { png "textures/bricks.png" map_type 2 interpolate 2 } scale <1, 0.5, 1> }
  normal { normal_map { png "textures/bricks-normal.png" map_type 2 } scale <1, 0.5, 1> }
  finish { ambient 0.2 diffuse 0.8 }
  scale <0.8, 1.6, 0.8>
  translate <3.2, 0.6, -0.5>
}
