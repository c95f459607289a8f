// A glass sphere over a floor lit by one point light, with photons: the sphere casts a dark
// shadow (its light arrives as photons only) with a bright caustic in it
// (tests/stochastic_probes.rs).
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.02 } }
camera { location <0, 4, -5> look_at <0, 0.6, 0> angle 40 }
light_source { <0, 8, 0> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
sphere {
  <0, 1.2, 0>, 1
  pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { ior 1.5 }
  photons { target refraction on reflection on }
}
