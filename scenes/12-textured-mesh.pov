// Textured mesh: Keenan Crane's "Spot" (OBJ with UVs, models/spot/, public domain) with its colour map by uv_mapping.
// rays render --scene textured-mesh --spp 4
camera {
  location <2.2, 1.1, 2.4>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 0.25, 0>
}

light_source { <4, 6, 5> color rgb <1.1, 1.1, 1.1> }
light_source { <-5, 3, 1> color rgb <0.35, 0.35, 0.4> }

plane { <0, 1, 0>, -0.74 pigment { image_map { png "textures/checker.png" interpolate 2 } rotate <90, 0, 0> scale 3 } finish { ambient 0.25 diffuse 0.7 } }

obj_mesh { "models/spot/spot_triangulated.obj.gz" smooth
  pigment { uv_mapping image_map { png "models/spot/spot_texture.png" interpolate 2 } }
  finish { ambient 0.2 diffuse 0.8 specular 0.2 roughness 0.3 }
  rotate <0, 150, 0>
}

// A brick sphere behind, normal-mapped.
sphere { <-0.6, 0, -1.7>, 0.75
  pigment { image_map { png "textures/bricks.png" map_type 1 interpolate 2 } }
  normal { normal_map { png "textures/bricks-normal.png" map_type 1 strength 1.5 } }
  finish { ambient 0.2 diffuse 0.8 specular 0.3 roughness 0.3 }
}
