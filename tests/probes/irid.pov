// irid without turbulence (render::irid): each light's diffuse term times
// 1 + amount·cos(π·thickness·(cos θ_light + cos θ_view)/λ), λ = 0.35, 0.26, 0.24 for the
// default irid_wavelength (measured with 16-bit renders of a sphere and of a plane lit from
// several angles; docs/textures.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -8> color 1 }
light_source { <8, -2, -3> color rgb <0.5, 0.6, 0.7> }
sphere { <-1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { ambient 0.05 diffuse 0.4 irid { 0.5 thickness 0.3 } } }
sphere { <1.1, 1.1, 0>, 1 pigment { rgb <1, 0.7, 0.4> } finish { ambient 0.05 diffuse 0.5 irid { 0.3 thickness 1.2 } phong 0.5 } }
sphere { <-1.1, -1.1, 0>, 1 pigment { rgb 1 } finish { ambient 0.05 diffuse 0.3 irid { 0.8 thickness 0.6 } } }
sphere { <1.1, -1.1, 0>, 1 pigment { rgb <0.6, 0.8, 1> } finish { diffuse 0.4 irid { 0.25 thickness 2 } } normal { bumps 0.4 scale 0.3 } }
