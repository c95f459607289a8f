#version 3.7;
global_settings { assumed_gamma 1.0 }

// glass.pov -- lancer example scene
//
// A pyrex-like glass sphere (ior 1.474, Fresnel reflection, energy
// conserving) standing in front of a green ball on a checker floor.
// Behind it there is a small "landscape" (coloured boxes, cones,
// cylinders and a sky gradient), which the glass ball shows upside
// down and left-right swapped, like a lens.
//
// References: reference/glass.png (-A) and glass_aa.png (+A0.3), 320x240,
// rendered by scripts/make_references.sh.

camera {
  location <0, 1.5, -5.5>
  look_at  <0, 1.0, 0>
  angle 48
  right x*image_width/image_height
}

light_source { <-8, 12, -6> color rgb <1, 0.97, 0.9> }
light_source { <6, 6, -8> color rgb <0.3, 0.32, 0.38> shadowless }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0.00 color rgb <0.95, 0.80, 0.60>]
      [0.52 color rgb <0.95, 0.80, 0.60>]
      [0.60 color rgb <0.55, 0.70, 0.95>]
      [1.00 color rgb <0.08, 0.18, 0.55>]
    }
    scale 2
    translate -y
  }
}

plane {
  y, 0
  pigment {
    checker color rgb <0.90, 0.88, 0.80> color rgb <0.55, 0.12, 0.10>
  }
  finish { ambient 0.06 diffuse 0.8 }
}

// --- the glass ball ---
sphere {
  <0, 1.0, 0>, 1.0
  pigment { color rgbf <0.97, 1.0, 0.98, 0.95> }
  finish {
    ambient 0 diffuse 0
    specular 0.7 roughness 0.001
    reflection { 0.0, 1.0 fresnel on }
    conserve_energy
  }
  interior { ior 1.474 }
}

// --- the green ball behind it ---
sphere {
  <1.15, 0.6, 2.4>, 0.6
  pigment { color rgb <0.10, 0.70, 0.15> }
  finish { ambient 0.08 diffuse 0.8 phong 0.6 phong_size 50 }
}

// --- the landscape behind ---
#declare Land_Finish = finish { ambient 0.08 diffuse 0.8 }

#macro Tower(P, R, Ht, Col)
  union {
    cylinder { <0, 0, 0>, <0, Ht, 0>, R }
    cone { <0, Ht, 0>, R * 1.3, <0, Ht + R * 2.5, 0>, 0 }
    pigment { color rgb Col }
    finish { Land_Finish }
    translate P
  }
#end

Tower(<-4.5, 0, 11.0>, 0.50, 3.2, <0.95, 0.85, 0.20>)
Tower(< 5.0, 0, 13.0>, 0.60, 4.2, <0.20, 0.45, 0.95>)
Tower(<-0.6, 0, 14.0>, 0.45, 2.4, <0.85, 0.35, 0.85>)
Tower(< 1.8, 0, 9.5>,  0.30, 1.4, <0.95, 0.95, 0.95>)

box {
  <-1, 0, -1>, <1, 1.8, 1>
  rotate y*25
  translate <-2.8, 0, 8.0>
  pigment { color rgb <0.95, 0.45, 0.10> }
  finish { Land_Finish }
}
box {
  <-1.5, 0, -0.7>, <1.5, 1.1, 0.7>
  rotate -y*15
  translate <3.2, 0, 7.5>
  pigment { color rgb <0.90, 0.90, 0.95> }
  finish { Land_Finish }
}
torus {
  0.9, 0.3
  rotate x*90
  translate <1.2, 1.2, 12.0>
  pigment { color rgb <0.95, 0.15, 0.20> }
  finish { Land_Finish }
}
