// Bump depth under scaling (render::normal): uniform scale keeps slopes, a stretch and
// no_bump_scale change them; a light just behind the plane still lights the tilted normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 4*x up 3*y }
light_source { <-1000, 0, 60> color 1 parallel point_at 0 }
light_source { <0, 1000, -300> color 0.5 parallel point_at 0 }
#declare F = finish { ambient 0.05 diffuse 0.9 };
plane { -z, 0 clipped_by { box { <-2, 0, -1>, <0, 1.5, 1> } } pigment { rgb 1 } finish { F }
  normal { gradient x 1 scale 0.25 } }
plane { -z, 0 clipped_by { box { <0, 0, -1>, <2, 1.5, 1> } } pigment { rgb 1 } finish { F }
  normal { gradient x 1 scale 0.25 no_bump_scale } }
plane { -z, 0 clipped_by { box { <-2, -1.5, -1>, <0, 0, 1> } } pigment { rgb 1 } finish { F }
  normal { gradient x 1 scale <0.25, 1, 0.5> rotate z*30 } }
plane { -z, 0 clipped_by { box { <0, -1.5, -1>, <2, 0, 1> } } pigment { rgb 1 } finish { F }
  normal { function { x * x } 1 scale 0.5 accuracy 0.2 } }
