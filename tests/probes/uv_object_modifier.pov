// `uv_mapping` as an object modifier maps the textures given after it by the surface's uv
// coordinates, as `texture { uv_mapping ... }` does (advanced/benchmark uses it on a mesh2), and
// the object's later transforms do not move the uv-mapped pattern.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,1,-4> look_at 0 }
light_source { <3,5,-5> rgb 1 }
#declare T = texture { pigment { checker rgb 1 rgb <0,0,0.5> scale 0.1 } }
sphere { 0, 0.5 uv_mapping texture { T } rotate 30*y scale 2 }
