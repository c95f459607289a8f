// light_group (povray 3.7.0, not the manual): a group's lights light only its own objects;
// objects outside it still cast shadows for them; a nested group's objects see only their
// own group's lights, and the outermost group's global_lights decides for all (off here).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.5, 0> }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.8 } }
light_source { <-5, 8, -5> rgb <0.3, 0.3, 1> }
box { <1.2, 2.2, -0.5>, <1.8, 2.4, 0.5> pigment { rgb <1, 1, 0> } }
light_group {
  light_source { <-2, 6, -6> rgb <1, 0.3, 0.3> }
  sphere { <0, 1, 0>, 1 pigment { rgb 1 } finish { ambient 0.05 diffuse 0.8 } }
  light_group {
    light_source { <-3, 1, -3> rgb <0.2, 1, 0.2> }
    sphere { <-2.2, 0.6, 0>, 0.6 pigment { rgb 1 } finish { ambient 0.05 diffuse 0.8 } }
    global_lights on
  }

}
