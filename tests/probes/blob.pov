// Blobs: sphere and capped cylinder components, component transforms, negative strength, the old component syntax, sturm, and per-component textures blended by field strength.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,4,-9> look_at <0,0.3,0> angle 50 }
light_source { <4,8,-6> rgb 1 }
light_source { <-6,3,-4> rgb 0.4 }
background { rgb <0.2,0.3,0.5> }
blob { threshold 0.5
  sphere { <-3,0,0>, 1.2, 1 }
  sphere { <-2,0.3,0>, 1, 1 scale <1,2,1> }
  cylinder { <-1,0,0>, <1,1,0>, 0.7, 1.2 }
  cylinder { <1,1,0>, <3,-0.5,1>, 0.6, strength 1 rotate 10*y }
  sphere { <0.2,0.7,-0.2>, 0.8, -1.5 }
  component 1, 1, <2.5,0.5,-1.5>
  pigment { rgb <1,0.6,0.3> } finish { phong 0.6 }
}
blob { threshold 0.6
  sphere { <0,0,0>, 1, 1 pigment { rgb <1,0,0> } }
  sphere { <0.7,0,0>, 1, 1 pigment { rgb <0,0,1> } translate y*0.3 }
  cylinder { <0,-1,0>, <0.5,1,0>, 0.5, 2 }
  sturm pigment { rgb <0.2,1,0.2> }
  scale 1.2 rotate 30*y translate <-0.5,0.5,2.5>
}
plane { y, -1.5 pigment { checker rgb 1 rgb 0.5 } }
