// Pattern normals by the slope of their value (render::normal): gradient with an amount,
// onion with frequency and sine wave, leopard, radial, lit from the side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -4> color 1 }
#declare F = finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 };
sphere { <-1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { gradient x, 2 scale 0.3 } }
sphere { <1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { onion 1.5 frequency 3 sine_wave scale 0.5 } }
sphere { <-1.1, -1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { leopard 3 scale 0.1 } }
sphere { <1.1, -1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { radial 1 frequency 8 rotate x*90 } }
