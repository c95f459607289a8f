// Method 3's split test scales with the interval's length: emission-only boxes 4 deep whose
// density is a step (z > 4x), summed light 0.18 per unit. Top: aa_threshold 0.6, split
// (0.18 x 4 = 0.72 > 0.6; the light per unit alone is below it). Middle: 0.8, no split.
// Bottom: intervals 2 with 0.5: each half is sampled apart and tested with its own length
// (0.36 < 0.5), so nothing splits. See scripts/measure_media_sampling.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> direction z right x up y }
#macro Slab(Y0, T, I)
box { <0, Y0, 0>, <1, Y0 + 1/3, 4> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { emission <0.09, 0.06, 0.03> method 3 samples 7, 7 intervals I
    aa_threshold T density { function { z > 4 * x } } } } }
#end
Slab(2/3, 0.6, 1)
Slab(1/3, 0.8, 1)
Slab(0, 0.5, 2)
background { rgb 0 }
