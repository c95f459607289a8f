#version 3.7;
global_settings { assumed_gamma 1.0 }
// text: timrom glyphs extruded along +z (caps and curved side walls), kerning ("AV"), a float
// offset moving each glyph up too, shadows on a plane; font found on the library path.
camera { location <1.1,1.4,-3> look_at <1.1,0.3,0> angle 50 }
light_source { <-4,6,-5> rgb 1 }
plane { y, -0.2 pigment { rgb 0.6 } }
text { ttf "timrom.ttf" "AVg" 0.4, 0.05 pigment { rgb <0.9,0.4,0.2> } finish { phong 0.5 } rotate y*-20 }
text { internal 2 "Qo" 0.2, 0 pigment { rgb <0.3,0.5,0.9> } scale 0.6 rotate x*70 translate <1.3,-0.19,-0.9> }
