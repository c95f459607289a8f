#version 3.7;
global_settings { assumed_gamma 1.0 }

// height_fields.pov -- lancer example scene
//
// Terrain from function height fields: a smooth one (corner normals
// mixed across each cell) with a water plane cutting it at its
// water_level, and a faceted one cut by a sphere in a CSG intersection
// (the field's solid reaches below y = 0, so the sphere's lower half stays).
//
// References: reference/height_fields*.png, 320x240, rendered by
// scripts/make_references.sh.

camera { location <0.5, 1.1, -0.9> look_at <0.5, 0.1, 0.55> angle 60 }
light_source { <4, 6, -3> rgb 1 }
light_source { <-3, 4, -2> rgb 0.3 shadowless }
background { rgb <0.45, 0.6, 0.85> }

#declare Land = function {
  0.45 + 0.25*sin(x*8)*cos(y*6) + 0.12*sin(x*21 + y*17) + 0.05*cos(x*43 - y*37)
}

height_field {
  function 120, 100 { Land(x, y, 0) }
  smooth
  water_level 0.3
  pigment { rgb <0.55, 0.7, 0.35> }
  finish { specular 0.2 roughness 0.05 }
  scale <1, 0.35, 1>
}

plane {
  y, 0.3*0.35
  pigment { rgbf <0.2, 0.35, 0.6, 0.6> }
  finish { reflection 0.3 }
}

intersection {
  height_field { function 60, 60 { 0.6 + 0.3*sin(x*12)*sin(y*9) } }
  sphere { <0.5, 0, 0.5>, 0.5 }
  pigment { rgb <0.8, 0.6, 0.45> }
  scale 0.35
  translate <0.9, 0, 0.95>
}
