// tiling 5 (render::tiling): rhombi of side 1 in hexagons, three tile types, each bevelled
// linearly from type/3 at its middle to (type+1)/3 at its edges (scripts/measure_tiling.py).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 6, -4> look_at <0.3, 0, 0.2> angle 50 }
light_source { <-10, 20, -10> color 1 }
plane { y, 0 pigment { tiling 5 color_map { [0 rgb <1,0.2,0.1>] [0.3 rgb <0.3,0,0>] [1/3 rgb <0,1,0.3>]
  [0.6 rgb <0,0.3,0>] [2/3 rgb <0.2,0.3,1>] [1 rgb <1,1,1>] } scale 0.8 rotate 10*y } }
