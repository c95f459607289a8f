#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { omnimax location 0 look_at z RIGHT }
#declare G = function(v) { (v+1)/2 }
sky_sphere { pigment { average pigment_map {
  [1 gradient x scale 2.0001 translate -x*1.00005 color_map { [0 rgb 0] [1 rgb <3,0,0>] }]
  [1 gradient y scale 2.0001 translate -y*1.00005 color_map { [0 rgb 0] [1 rgb <0,3,0>] }]
  [1 gradient z scale 2.0001 translate -z*1.00005 color_map { [0 rgb 0] [1 rgb <0,0,3>] }]
} } }
