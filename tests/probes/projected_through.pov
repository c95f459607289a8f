// projected_through: light reaches the floor only along paths that cross the declared box;
// the sphere between the light and the box casts no shadow, the small box between the floor
// and the projecting box does, and the projecting box itself is not drawn.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -6> look_at <0, 0, 0> }
#declare Gate = box { <-1, 2.9, -0.6>, <1, 3, 0.6> rotate 20*y }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0, 5, 0>, 0.4 pigment { rgb <1, 0, 0> } }
box { <-0.2, 1, -0.2>, <0.2, 1.2, 0.2> pigment { rgb <0, 0, 1> } }
light_source { <0, 8, 0> rgb 1 projected_through { Gate } }
light_source { <5, 5, -5> rgb 0.3 }
