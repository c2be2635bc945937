// Feature lines: the Stanford bunny ringed by four spheres: outline, intersection and self-occlusion.
// rays render --scene bunny-lines --edges silhouette,occlusion,intersection,crease
// The bunny: models/stanford-bunny.obj.gz (Stanford 3D Scanning Repository; models/README.md).
camera {
  location <-0.04, 0.16, 0.27>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <-0.017, 0.095, 0>
}

light_source { <-1, 2, 1.5> color rgb <1.1, 1.1, 1.1> }
light_source { <1, 0.6, 1> color rgb <0.3, 0.3, 0.35> }

plane { <0, 1, 0>, 0.034 pigment { color rgb <0.9, 0.88, 0.82> } finish { ambient 0.2 diffuse 0.7 } }

sphere { <-0.085, 0.05, 0.045>, 0.035 pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.1 } }
sphere { <0.05, 0.055, 0.035>, 0.03 pigment { color rgb <0.2, 0.5, 0.9> } finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.1 } }
sphere { <0.045, 0.07, -0.05>, 0.035 pigment { color rgb <0.3, 0.8, 0.3> } finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.1 } }
sphere { <-0.095, 0.06, -0.045>, 0.035 pigment { color rgb <0.95, 0.8, 0.2> } finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.1 } }

obj_mesh { "models/stanford-bunny.obj.gz"
  pigment { color rgb <0.8, 0.8, 0.8> }
  finish { ambient 0.2 diffuse 0.7 specular 0.2 roughness 0.3 }
}
