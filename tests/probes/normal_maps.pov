// normal_map, average, slope_map and a block pattern's normal list (render::normal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -4> color 1 }
#declare F = finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 };
box { <-2.1, 0.1, 0>, <-0.1, 2.1, 1> pigment { rgb 1 } finish { F }
  normal { gradient x normal_map { [0.3 gradient y, 2 scale 0.2] [0.7 onion 1 scale 0.2] } } }
box { <0.1, 0.1, 0>, <2.1, 2.1, 1> pigment { rgb 1 } finish { F }
  normal { average normal_map { [1 gradient x, 3 scallop_wave scale 0.3] [1 gradient y, 3 triangle_wave scale 0.3] } } }
box { <-2.1, -2.1, 0>, <-0.1, -0.1, 1> pigment { rgb 1 } finish { F }
  normal { gradient x 1 scale 0.5 slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] } } }
box { <0.1, -2.1, 0>, <2.1, -0.1, 1> pigment { rgb 1 } finish { F }
  normal { checker normal { gradient x 2 scale 0.2 } normal { gradient y 2 scale 0.2 } scale 0.5 } }
