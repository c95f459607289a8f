// sky_sphere_filter.pov before #version 3.7: a filtering layer still tints the background,
// but lets the sky layers below it through untinted, f + t of them (measured with povray on
// two and three layers; render::trace background).
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location 0 look_at z angle 100 }
background { rgb <1, 0.5, 0.2> }
sky_sphere {
  pigment { gradient x color_map { [0 rgbf <0.5, 0.8, 0.5, 0.6>] [1 rgb <0.2, 0.3, 0.9>] } scale 2 translate -x }
  pigment { gradient y color_map { [0 rgbf <0.9, 0.3, 0.6, 0.5>] [0.5 rgbt <0.1, 0.9, 0.2, 0.7>] [1 rgbft <0.6, 0.6, 0.1, 0.3, 0.3>] } scale 2 translate -y }
  pigment { bozo color_map { [0 rgbf <1, 1, 1, 1>] [1 rgbf <0.3, 0.3, 0.3, 0.8>] } scale 0.3 }
}
