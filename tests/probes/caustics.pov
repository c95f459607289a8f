// Fake caustics (interior { caustics }), measured with scripts/measure_caustics.sh: a shadow
// ray's light is multiplied by 1 + |cos|^(45*caustics) at each crossing of such a surface, cos
// between the light direction and the normal turned to face the shadow ray, then perturbed by
// the surface's normal pattern. A bumpy caustic plane, a tilted caustic slab and a plain glass
// slab (no caustics) over a white floor, lit from straight above.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 5, 0> look_at 0 right 8*x up 6*z }
light_source { <0, 1000, 0> rgb 0.3 parallel point_at 0 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-4, 1, -3>, <0, 1.01, 3> hollow pigment { rgbf <1, 0.9, 0.8, 1> } finish { ambient 0 diffuse 0 }
  interior { caustics 0.7 } normal { bumps 0.5 scale 0.7 } }
box { <0.2, 0.9, -3>, <4, 1, 0> hollow pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }
  interior { caustics 1.5 } rotate 8*z }
box { <0.2, 0.9, 0.2>, <4, 1, 3> hollow pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 } }
