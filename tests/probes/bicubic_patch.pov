// bicubic_patch: a coarse type 0 patch (2^2 x 2^2 pieces, so the triangulation shows), a fine
// type 1 one, and a patch in CSG (a patch has no inside: intersection keeps its part inside the box).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-9> look_at <0,0,0> angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
#declare P = bicubic_patch { type 0 flatness 0 u_steps 2 v_steps 2
   < 0.0, 0.0, 2.0>, < 1.0, 0.0, 0.0>, < 2.0, 0.0, 0.0>, < 3.0, 0.0, -2.0>,
   < 0.0, 1.0, 0.0>, < 1.0, 1.0, 0.0>, < 2.0, 1.0, 0.0>, < 3.0, 1.0,  0.0>,
   < 0.0, 2.0, 0.0>, < 1.0, 2.0, 0.0>, < 2.0, 2.0, 0.0>, < 3.0, 2.0,  0.0>,
   < 0.0, 3.0, 2.0>, < 1.0, 3.0, 0.0>, < 2.0, 3.0, 0.0>, < 3.0, 3.0, -2.0>
   translate <-1.5,-1.5,0> }
object { P pigment { rgb <1,0.5,0.2> } finish { phong 0.6 } rotate <30,-60,0> translate <-2.6,0,0> }
bicubic_patch { type 1 flatness 0.05 u_steps 4 v_steps 4 uv_vectors <0,0>, <1,0>, <1,1>, <0,1>
   < 0.0, 0.0, 2.0>, < 1.0, 0.0, 0.0>, < 2.0, 0.0, 0.0>, < 3.0, 0.0, -2.0>,
   < 0.0, 1.0, 0.0>, < 1.0, 1.0, 0.0>, < 2.0, 1.0, 0.0>, < 3.0, 1.0,  0.0>,
   < 0.0, 2.0, 0.0>, < 1.0, 2.0, 0.0>, < 2.0, 2.0, 0.0>, < 3.0, 2.0,  0.0>,
   < 0.0, 3.0, 2.0>, < 1.0, 3.0, 0.0>, < 2.0, 3.0, 0.0>, < 3.0, 3.0, -2.0>

   translate <-1.5,-1.5,0> pigment { rgb <0.3,0.9,0.3> } rotate <-40,30,0> }
intersection { object { P } box { -1, 1 } pigment { rgb <0.4,0.4,1> } rotate <20,40,0> translate <2.6,0,0> }
