// no_reflection: measured with povray, a no_image object is unseen by camera rays and by their
// continuations through glass (ior 1.0 and 1.5), and seen in a mirror; a no_reflection one
// the other way round. Shadows are not affected.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 5, -10> rgb 1 }
plane { z, 3 pigment { rgb <0, 0, 1> } finish { ambient 0.6 diffuse 0.4 } }
sphere { <-1.2, 0, 0>, 0.6 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } no_reflection }
union {
  sphere { <1.2, 0, 0>, 0.6 }
  sphere { <1.2, 0.7, 0>, 0.3 }
  pigment { rgb <1, 1, 0> } finish { ambient 1 diffuse 0 }
  no_reflection
}
box { <0.3, -1, -2>, <2.5, 1, -1.9> pigment { rgbt 1 } interior { ior 1.5 } }
box { <-2.5, -1, -2>, <-0.3, 1, -1.9> pigment { rgbt 1 } interior { ior 1.0 } }
plane { y, -1 pigment { rgb 0.1 } finish { reflection 0.8 ambient 0.1 diffuse 0.3 } }
