// Media: the five scattering types lit from one side and from behind, extinction 1 (the
// scattering colour dims what lies behind too). Phase scales measured with povray 3.7:
// isotropic 1, Rayleigh 0.79935(1 + cos^2), Henyey-Greenstein (1 - g^2)/(1 + g^2 - 2g cos)^1.5.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x*10 up y*4 }
background { rgb 0.1 }
light_source { <300, 200, 1000>, rgb 1 }
#macro Cell(X, T)
  box { <X - 0.9, -1.8, 0>, <X + 0.9, 1.8, 1> hollow no_shadow pigment { rgbt 1 }
    finish { ambient 0 diffuse 0 }
    interior { media { scattering { T, <0.05, 0.08, 0.1> #if (T = 5) eccentricity 0.6 #end } samples 3 } } }
#end
Cell(-4, 1) Cell(-2, 2) Cell(0, 3) Cell(2, 4) Cell(4, 5)
