// A shadowless light scatters nothing in media: the box of scattering media is lit by a
// shadowed light from the right (its density step x > 0.6 shadows the thin part) and by a
// brighter shadowless light from the left, which adds nothing (measured: lit by the
// shadowless light alone the box stays black; scripts/measure_media_shadow.sh).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> direction z right x up y }
light_source { <100, 0.5, 0.5> rgb <1, 0.8, 0.6> }
light_source { <-100, 0.5, 0.5> rgb 2 shadowless }
box { <0, 0, 0>, <1, 1, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { scattering { 1, 3 extinction 1 } method 3 samples 3, 3
    density { function { select(x - 0.6, 0.05, 1) } } } } }
background { rgb 0 }
