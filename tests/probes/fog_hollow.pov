// Fog only outside solid objects: the camera sits inside plane { z, 10 }'s solid half-space,
// so the wall and the sphere in front of it are seen unfogged; the hollow box's contents and
// the sphere past the wall (in the other, fogged world) show the rule from both sides.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location 0 direction z look_at <0, 0, 5> }
plane { z, 10 pigment { rgb 0.2 } finish { ambient 1 diffuse 0 } }
sphere { <1, 0, 5>, 0.5 pigment { rgb <0.2, 0.5, 0.2> } finish { ambient 1 diffuse 0 } }
box { <-2, -1, 4>, <-0.5, 1, 6> pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 } hollow }
sphere { <-1.2, 0, 5>, 0.4 pigment { rgb <0.5, 0.2, 0.2> } finish { ambient 1 diffuse 0 } }
fog { distance 6 color rgb <0.9, 0.9, 1> }
