// Interior fade: light leaving a fading interior is dimmed by the stretch inside (the far surface's own light is not), 1/(1+(d/fd)^fp) or exp from 1000, tinted by fade_color; shadow rays too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-6> look_at <0,0.8,0> angle 45 }
light_source { <3,6,-4> rgb 1 }
background { rgb <0.3,0.4,0.6> }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
sphere { <-1.2,1,0>, 1 pigment { rgbf <1,1,1,0.9> } finish { phong 0.5 } interior { ior 1.4 fade_distance 0.8 fade_power 2 fade_color <0.2,0.6,1> } }
box { <0.3,0.05,-0.7>, <2,1.6,0.7> pigment { rgbt <1,1,1,0.9> } interior { fade_distance 1 fade_power 1001 fade_color <1,0.3,0.1> } }
