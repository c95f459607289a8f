// A scene with no #version directive and no assumed_gamma: povray 3.7 turns gamma
// correction off, as for a pre-3.7 scene (a #version in an included file, or +MV3.7,
// would turn it on).
camera { location <0, 0, -3> look_at 0 }
light_source { <-2, 3, -10> rgb 1 }
sphere { 0, 1 pigment { rgb <0.3, 0.5, 0.8> } finish { ambient 0.2 diffuse 0.6 phong 0.5 } }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.7 } }
