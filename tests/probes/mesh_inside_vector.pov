// A closed mesh with inside_vector is a solid: CSG keeps the sphere's part inside the mesh
// cube (intersection) and cuts the cube by the sphere (difference); mesh and mesh2 alike.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,3,-6> look_at 0 angle 50 }
light_source { <-5,10,-8> rgb 1 }
background { rgb <0.2,0.3,0.5> }
#declare P = array[8] { <-1,-1,-1>, <1,-1,-1>, <1,1,-1>, <-1,1,-1>, <-1,-1,1>, <1,-1,1>, <1,1,1>, <-1,1,1> }
#macro T(A,B,C) triangle { P[A], P[B], P[C] } #end
#declare Cube = mesh {
  T(0,1,2) T(0,2,3) T(4,6,5) T(4,7,6) T(0,4,5) T(0,5,1)
  T(3,2,6) T(3,6,7) T(0,3,7) T(0,7,4) T(1,5,6) T(1,6,2)
  inside_vector <0.1,0.2,1> hierarchy on
}
#declare Cube2 = mesh2 {
  vertex_vectors { 8, P[0], P[1], P[2], P[3], P[4], P[5], P[6], P[7] }
  face_indices { 12, <0,1,2>, <0,2,3>, <4,6,5>, <4,7,6>, <0,4,5>, <0,5,1>, <3,2,6>, <3,6,7>, <0,3,7>, <0,7,4>, <1,5,6>, <1,6,2> }
  inside_vector <0.1,0.2,1>
}
intersection { object { Cube } sphere { 0, 1.3 } pigment { rgb <1,0.6,0.3> } translate -x*1.6 }
difference { object { Cube2 } sphere { <0.5,0.5,-0.5>, 1 } pigment { rgb <0.4,0.8,1> } translate x*1.6 }
