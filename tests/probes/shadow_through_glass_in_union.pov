#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,3,-4> look_at 0 angle 50 }
light_source { <0,10,0> rgb 1 }
plane { y, -1 pigment { rgb 1 } }
union {
  sphere { 0, 0.7 pigment { rgbf <0.9,0.6,0.3,0.9> } interior { ior 1.3 } }
  box { <1,-0.5,-0.5>, <2,0.5,0.5> pigment { rgb <0.2,0.5,0.9> } }
}
