// mesh_camera distribution 3: the pixel's uv point on a uv-mapped mesh2 gives the ray's origin
// (povray takes a pixel at its corner, the top row at y = 0.5 and the right-most column at
// width - 1.5), with the vertex normals interpolated under `smooth`.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0, 0, 1> }
#declare Q = mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <8, 0, 0>, <8, 6, 0>, <0, 6, 0> }
  normal_vectors { 4, <0, 0, 1>, <0.3, 0, 1>, <0.3, 0.3, 1>, <0, 0.3, 1> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 2, 1>, <0, 3, 2> }
}
camera { mesh_camera { 1 3 mesh { Q } smooth } }
plane { -z, -1
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb 0] [1 rgb <2, 0, 0>] } scale 8.5]
    [1 gradient y color_map { [0 rgb 0] [1 rgb <0, 2, 0>] } scale 6.5] } }
  finish { ambient 1 diffuse 0 } }
