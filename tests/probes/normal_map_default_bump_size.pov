// Normals inside a normal_map or a block pattern's list start from the #default normal's
// bump_size (1.5 here), as the texture's own normal does (measured with povray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 }
light_source { <200, 200, -100> color rgb 1 }
#default { normal { bump_size 1.5 } }
box { <-4, 0, 0>, <4, 3, 1> pigment { rgb 1 }
  normal { gradient x normal_map { [0.3 gradient y scallop_wave scale 0.3] [0.7 gradient y scallop_wave scale 0.3] } } }
box { <-4, -3, 0>, <4, 0, 1> pigment { rgb 1 }
  normal { checker normal { gradient x scallop_wave scale 0.3 } normal { gradient y triangle_wave scale 0.2 } } }
