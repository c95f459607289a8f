// caustic_sphere with dispersion: coloured rims in the glass and round its caustic
// (tests/stochastic_probes.rs).
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.02 } }
camera { location <0, 4, -5> look_at <0, 0.6, 0> angle 40 }
light_source { <0, 8, 0> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
sphere {
  <0, 1.2, 0>, 1
  pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { ior 1.5 dispersion 1.15 dispersion_samples 7 }
  photons { target refraction on reflection on }
}
