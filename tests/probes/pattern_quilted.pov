// quilted as a pigment and as a normal (render::pattern::quilted_vector): the cushion vector
// d·(2/√3)·B(|d|), d the offset from the unit cube's centre, B the Bézier through 0, control0,
// control1, 1; the value is a third of its |x|+|y|+|z|, the normal n + amount·vector
// (scripts/measure_pattern.py, scripts/measure_normals.py; docs/textures.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -4> color 1 }
#declare F = finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 };
plane { z, 1.2 pigment { quilted color_map { [0 rgb <0,0,0.5>] [0.6 rgb <1,1,0.8>] } scale 0.7 } }
sphere { <-1.1, 1.1, 0>, 1 pigment { quilted control0 0 control1 0.5 color_map { [0 rgb 0] [0.5 rgb <1,0.3,0.1>] } scale 0.4 } finish { F } }
sphere { <1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { quilted 0.8 scale 0.35 } }
sphere { <-1.1, -1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { quilted 1 control0 0.5 control1 1 scale 0.3 rotate 20*y } }
sphere { <1.1, -1.1, 0>, 1 pigment { rgb <1,0.8,0.6> } finish { F } normal { quilted 0.6 control0 0 control1 0 scale 0.3 warp { turbulence 0.3 } } }
