// A checker floor seen at a slant through a focal-blur camera: sharp at the focal point's
// distance, blurred nearer and farther (tests/stochastic_probes.rs).
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  location <0, 2, -4> look_at <0, 0, 2>
  aperture 0.8 blur_samples 60, 200 focal_point <0, 0, 2> confidence 0.95 variance 1/20000
}
light_source { <3, 10, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.1, 0.2, 0.5> scale 0.7 } finish { ambient 0.2 } }
sphere { <1.2, 0.6, 0.5>, 0.6 pigment { rgb <1, 0.4, 0.2> } }
