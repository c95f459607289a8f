// Fog turbulence (measured with scripts/measure_fog_turbulence.sh): the fog's depth along a ray
// d long shrinks by 1 - min(turb_depth*T, 1)*exp(-d/distance), T the scalar turbulence at
// turbulence * (the ray's midpoint). A ground fog and a constant fog, both stirred, over a
// chequered floor and a wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 0> angle 70 }
light_source { <5, 20, -10> rgb 1 }
plane { y, 0 pigment { checker rgb 0.2 rgb 0.8 } }
plane { -z, -12 pigment { rgb <0.3, 0.4, 0.9> } }
fog { fog_type 2 distance 15 color rgb <0.9, 0.8, 0.7> fog_offset 0.5 fog_alt 1.5
  turbulence <0.8, 0.4, 0.6> turb_depth 0.7 octaves 5 omega 0.6 lambda 2.3 }
fog { distance 60 color rgb <0.5, 0.6, 0.7> turbulence 0.3 }
