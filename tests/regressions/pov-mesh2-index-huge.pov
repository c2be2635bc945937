mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 1e300> } }
