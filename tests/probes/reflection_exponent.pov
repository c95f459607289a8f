// reflection { exponent E }: the reflected colour is raised to 1/E before it is weighted
// (measured: reflection R of a background C shows R*C^(1/E)); with fresnel and a tinted
// minimum too, and the old `reflection_exponent`.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
background { rgb <0.6, 0.4, 0.2> }
plane { z, 8 pigment { checker rgb <0.9, 0.8, 0.3>, rgb <0.1, 0.3, 0.5> } finish { ambient 1 diffuse 0 } }
light_source { <3, 5, -4>, rgb 1 }
#macro Ball(X, F)
  sphere { <X, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.1, 0.05> } finish { F } interior { ior 1.5 } }
#end
Ball(-2.4, finish { reflection { 0.8 exponent 0.5 } })
Ball(-0.8, finish { reflection { 0.1, 0.95 fresnel on exponent 0.8 } })
Ball(0.8, finish { reflection { <0.2, 0.1, 0>, <0.9, 0.7, 0.5> exponent 2 } })
Ball(2.4, finish { reflection 0.6 reflection_exponent 0.3 })

plane { y, 0 pigment { rgb 0.1 } finish { reflection { 0.5 exponent 1.5 } } }
