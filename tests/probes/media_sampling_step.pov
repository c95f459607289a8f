// Method 3's sample points and weights: an emission-only box seen along z whose density is a
// step (z > x), so each column's light is the weight of the samples past x; the upper half
// with aa_threshold 1000 (no step split: points at 0, 0.1, ..., 0.8 of the depth for samples
// 7), the lower half with the default 0.1 (split twice near the edge); see
// scripts/measure_media_sampling.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> direction z right x up y }
#macro Slab(Y0, T)
box { <0, Y0, 0>, <1, Y0 + 0.5, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { emission <0.9, 0.6, 0.3> method 3 samples 7, 7 aa_threshold T
    density { function { z > x } } } } }
#end
Slab(0.5, 1000)
Slab(0, 0.1)
background { rgb 0 }
