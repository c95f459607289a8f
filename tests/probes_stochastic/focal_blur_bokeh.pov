// Bright points far behind the plane of sharpness blur into the bokeh's shape: a square as
// wide as the round lens, its left third four times as bright as the rest (pigment
// brightness weights the lens points), so the spots show the shape's size, orientation and
// weighting (tests/stochastic_probes.rs).
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  location 0 right 4/3*x up y direction 2*z
  aperture 0.6 blur_samples 500, 500 focal_point <0, 0, 1>
  bokeh { pigment { gradient x color_map { [0 rgb 1] [0.33 rgb 1] [0.33 rgb 0.25] [1 rgb 0.25] } } }
}
background { rgb 0 }
#for (i, -1, 1)
  sphere { <9*i, 0, 20>, 0.3 pigment { rgb 1.5 } finish { ambient 1 diffuse 0 } }
#end
