// uv_mapping on meshes: mesh2 uv_vectors with uv_indices (left) and a mesh of triangles with
// their own uv_vectors (right), each a quad whose uv runs differently from its shape.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at 0 right 4.8*x up 3.6*y }
#declare P = pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb <1,0.6,0.2>] } }
#declare Q = pigment { uv_mapping gradient y color_map { [0 rgb 0] [1 rgb <0.2,0.6,1>] } }
mesh2 {
  vertex_vectors { 4, <-1,-1,0>, <1,-1,0>, <1,1,0>, <-1,1.2,0> }
  uv_vectors { 4, <0,0>, <0.5,0.1>, <2,3>, <0.2,1> }
  face_indices { 2, <0,1,2>, <0,2,3> }
  uv_indices { 2, <0,1,2>, <3,2,1> }
  texture { pigment { P } finish { ambient 1 diffuse 0 } }
  rotate 20*z translate -1.2*x
}
mesh {
  triangle { <-1,-1,0>, <1,-1,0>, <1,1,0> uv_vectors <0,0>, <1,0>, <0.9,0.9> }
  smooth_triangle { <-1,-1,0>, -z, <1,1,0>, -z, <-1,1,0>, -z uv_vectors <0,0>, <0.7,0.9>, <0,0.95> }
  texture { pigment { Q } finish { ambient 1 diffuse 0 } }
  scale 0.9 translate <1.2,0.013,0>
}
