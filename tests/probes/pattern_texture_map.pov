#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare T1 = texture { pigment { rgb <0.9,0.3,0.1> } finish { ambient 0.2 diffuse 0.7 phong 0.6 } }
#declare T2 = texture { pigment { rgb <0.1,0.4,0.9> } finish { ambient 0.4 diffuse 0.5 phong 0.3 phong_size 10 } }
sphere { <-1.1,0,0>, 1 texture { gradient x texture_map { [0.1 T1] [0.9 T2] } scale 2 translate -x*2.1 } }
sphere { <1.1,0,0>, 1 texture { gradient y texture_map { [0.1 T1] [0.9 T2] } scale 2 translate -y } }
