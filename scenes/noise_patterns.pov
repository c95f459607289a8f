#version 3.7;
global_settings { assumed_gamma 1.0 }

// noise_patterns.pov -- lancer example scene
//
// A row of boxes and a floor, each painted with one of POV-Ray's noise-based
// patterns: bozo, granite, agate, marble with turbulence, crackle, wrinkles,
// and a wood floor with a turbulence warp. POV-Ray's noise generators 1 and 2
// come from a random table in its own source, which lancer does not copy, so
// lancer's features differ while their size, contrast and colours match; the
// reference test checks only that much (see reference/manifest.tsv).
//
// Reference: reference/noise_patterns.png (-A), 320x240, rendered by
// scripts/make_references.sh.

camera {
  location <0, 3, -9>
  look_at  <0, 0.6, 0>
  angle 50
  right x*image_width/image_height
}
light_source { <-6, 10, -8> rgb 1 }

#declare F = finish { ambient 0.25 diffuse 0.75 }

plane { y, 0
  pigment { wood color_map { [0 rgb <0.8,0.55,0.3>] [1 rgb <0.45,0.25,0.1>] }
            warp { turbulence 0.3 } scale 0.4 rotate y*80 }
  finish { F }
}
box { <-4.6,0,0>, <-3.2,1.6,1.4>
  pigment { bozo color_map { [0 rgb <0.1,0.2,0.7>] [1 rgb 1] } scale 0.3 } finish { F } }
box { <-2.9,0,0>, <-1.5,1.6,1.4>
  pigment { granite color_map { [0 rgb 0.9] [0.5 rgb <0.5,0.4,0.4>] [1 rgb 0.1] } } finish { F } }
box { <-1.2,0,0>, <0.2,1.6,1.4>
  pigment { agate scale 0.5 } finish { F } }
box { <0.5,0,0>, <1.9,1.6,1.4>
  pigment { marble turbulence 0.8 color_map { [0 rgb 1] [0.8 rgb <0.3,0.5,0.3>] [1 rgb 0] } scale 0.6 }
  finish { F } }
box { <2.2,0,0>, <3.6,1.6,1.4>
  pigment { crackle color_map { [0 rgb 0] [0.08 rgb <0.9,0.8,0.6>] [1 rgb <0.6,0.5,0.3>] } scale 0.35 }
  finish { F } }
sphere { <4.2,0.8,0.7>, 0.75
  pigment { wrinkles color_map { [0 rgb <0.6,0,0>] [1 rgb <1,0.9,0.5>] } scale 0.5 } finish { F } }
