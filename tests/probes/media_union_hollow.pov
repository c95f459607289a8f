// A camera inside a union (not hollow) of a transparent solid sphere and a hollow media
// sphere: POV-Ray judges a union by its members, so the media is computed once the ray has
// left the solid member (lancer had judged the union by its own flag and showed no media).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-5> look_at 0 }
light_source { <0,50,0> rgb 1 }
union {
  sphere { 0, 10 pigment { rgbt 1 } }
  sphere { 0, 1 scale 100 hollow texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
    interior { media { scattering { 5, 0.01 eccentricity 0.7 extinction 0.8 } intervals 3 method 3 } } }
}
sphere { <1,0,20>, 4 pigment { rgb <1,0.4,0.2> } }
