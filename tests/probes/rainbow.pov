// rainbow: the ring's place and map index (angle, width), a 180 degree arc whose ends fade
// by a smoothstep over the falloff, filtering by the rainbow's own share on a wall at a
// finite distance, and the background at povray's 2e10 units.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> direction z right 4/3*x up y angle 120 }
background { rgb <0.3, 0.3, 0.5> }
plane { -z, 0 pigment { rgb 1 } finish { ambient 1 diffuse 0 } clipped_by { plane { x, 0 } } }
rainbow { angle 30 width 20 distance 6 direction <0.1, 0.05, 1>
  color_map { [0 rgbf <1, 0, 0, 0.8>] [0.5 rgbt <0, 1, 0, 0.3>] [1 rgb <0, 0, 1>] }
  up <0.2, 1, 0> arc_angle 180 falloff_angle 90 }
