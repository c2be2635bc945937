// Depth of field: three cameras: focal distance 10 aperture 0.1; 10 and 0.25; 7 and 0.25.
// rays render --scene depth-of-field --camera 0|1|2
// Spheres stand every 3 units along the view; the one at distance 10 (or 7) is sharp.
camera {  // 0: focal distance 10, aperture 0.1
  location <0, 1, 12>  up <0, 1, 0>  right <1.33333, 0, 0>  look_at <0, 1, 0>
  aperture 0.1  focal_point <0, 1, 2>  blur_samples 32
}
camera {  // 1: focal distance 10, aperture 0.25
  location <0, 1, 12>  up <0, 1, 0>  right <1.33333, 0, 0>  look_at <0, 1, 0>
  aperture 0.25  focal_point <0, 1, 2>  blur_samples 32
}
camera {  // 2: focal distance 7, aperture 0.25
  location <0, 1, 12>  up <0, 1, 0>  right <1.33333, 0, 0>  look_at <0, 1, 0>
  aperture 0.25  focal_point <0, 1, 5>  blur_samples 32
}

light_source { <-5, 10, 14> color rgb <1.2, 1.2, 1.2> }

plane { <0, 1, 0>, 0 pigment { color rgb <0.8, 0.8, 0.75> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-2.4, 1, 8>, 0.9 pigment { color rgb <0.9, 0.2, 0.2> } finish { ambient 0.2 diffuse 0.7 specular 0.5 roughness 0.1 } }
sphere { <-0.8, 1, 5>, 0.9 pigment { color rgb <0.9, 0.7, 0.1> } finish { ambient 0.2 diffuse 0.7 specular 0.5 roughness 0.1 } }
sphere { <0.8, 1, 2>, 0.9 pigment { color rgb <0.2, 0.8, 0.3> } finish { ambient 0.2 diffuse 0.7 specular 0.5 roughness 0.1 } }
sphere { <2.4, 1, -1>, 0.9 pigment { color rgb <0.2, 0.4, 0.9> } finish { ambient 0.2 diffuse 0.7 specular 0.5 roughness 0.1 } }
sphere { <4.0, 1, -4>, 0.9 pigment { color rgb <0.7, 0.3, 0.9> } finish { ambient 0.2 diffuse 0.7 specular 0.5 roughness 0.1 } }
box { <-8, 0, -12>, <8, 6, -11> pigment { color rgb <0.3, 0.4, 0.6> } finish { ambient 0.3 diffuse 0.6 } }
