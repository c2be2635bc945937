camera { location <0,0,5> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }
light_source { <4,6,5> color rgb 1 }
mesh {
  triangle { <0,0,0>, <1,0,0>, <1,1,0> uv_vectors <0,0>, <1,0>, <1,1> }
  smooth_triangle { <0,0,0>, <0,0,1>, <1,1,0>, <0,0,1>, <0,1,0>, <0,0,1> }
  pigment { color rgb <1, 0.5, 0.2> }
}
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  normal_vectors { 4, <0,0,1>, <0,0,1>, <0,0,1>, <0,0,1> }
  uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }
  face_indices { 2, <0,1,2>, <0,2,3> }
  normal_indices { 2, <0,1,2>, <0,2,3> }
  uv_indices { 2, <0,1,2>, <0,2,3> }
  pigment { uv_mapping image_map { png "tex.png" } }
}
obj_mesh { "tiny.obj" smooth pigment { color rgb <0.9,0.8,0.7> } scale 2 rotate <0,30,0> }
