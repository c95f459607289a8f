// mesh2: vertex and normal vectors, normal_indices, a texture_list with per-face textures,
// and faces whose normals follow their vertex indices.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-5> look_at <0,0.5,0> angle 45 }
light_source { <3,5,-4> rgb 1 }
mesh2 {
  vertex_vectors { 5, <-1,0,-1>, <1,0,-1>, <1,0,1>, <-1,0,1>, <0,1.5,0> }
  normal_vectors { 5, <-1,0.5,-1>, <1,0.5,-1>, <1,0.5,1>, <-1,0.5,1>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb <1,0.4,0.2> } finish { phong 0.5 } }, texture { pigment { rgb <0.2,0.5,1> } } }
  face_indices { 4, <0,1,4>, 0, <1,2,4>, 1, <2,3,4>, 0, <3,0,4>, 1 }
  translate x*-1.2
}
mesh2 {
  vertex_vectors { 5, <-1,0,-1>, <1,0,-1>, <1,0,1>, <-1,0,1>, <0,1.5,0> }
  normal_vectors { 2, <0,1,0>, <0,0,-1> }
  face_indices { 4 <0,1,4> <1,2,4> <2,3,4> <3,0,4> }
  normal_indices { 4 <1,1,0> <1,1,0> <1,1,0> <1,1,0> }
  pigment { rgb <0.4,1,0.4> }
  translate x*1.2
}
plane { y, 0 pigment { rgb 0.8 } }
