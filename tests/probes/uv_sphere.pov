// uv_mapping on a sphere: u (gradient x, left) and v (gradient y, right). The object's
// rotation does not move a uv-mapped pattern; the pigment's own scale does.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at 0 right 4.8*x up 3.6*y }
sphere { 0, 1
  pigment { uv_mapping gradient x scale 0.5 color_map { [0 rgb 0] [1 rgb <1,0.5,0>] } }
  finish { ambient 1 diffuse 0 }
  rotate <30,40,0> translate -1.1*x
}
sphere { 0, 1
  texture {
    uv_mapping
    pigment { gradient y color_map { [0 rgb 0] [1 rgb <0,0.5,1>] } }
    finish { ambient 1 diffuse 0 }
    scale 0.5
  }
  rotate <30,40,0> translate 1.1*x
}
