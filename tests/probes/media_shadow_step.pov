// Where a shadow ray samples media: a parallel light shines along +y through a box of
// absorbing media onto a wall, the density a step (y > x), so each column's shadow is the
// weight of the samples past x along the shadow ray (from the wall towards the light): the
// view rule's points, n = samples/2 + 1 steps with samples at j·h, (j + ½)·h, (j + 1)·h,
// h = L/(n + 1). Upper half samples 7, lower half samples 3; see
// scripts/measure_media_shadow.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 1.2, 0.5> look_at <0.5, 2, 0.5> right -x up z }
light_source { <0.5, -1000, 0.5> rgb 1 parallel point_at <0.5, 0, 0.5> }
// Facing -y: its solid side lies beyond the wall, not around the box (no media inside solids).
plane { -y, -1.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#macro Slab(Z0, S)
box { <0, 0, Z0>, <1, 1, Z0 + 0.5> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { absorption <0.5, 1, 2> method 3 samples S, S
    density { function { y > x } } } } }
#end
Slab(0.5, 7)
Slab(0, 3)
