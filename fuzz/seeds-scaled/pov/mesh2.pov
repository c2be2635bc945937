#version 3.7;
camera { location -5*z look_at 0 }
mesh2 { vertex_vectors { 65536 @@, <0,0,0>@@ } face_indices { 65536 @@, <0,1,2>@@ } }
