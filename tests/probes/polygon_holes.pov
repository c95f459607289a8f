// Polygons: sub-polygons cutting holes where an even number overlap, and an unclosed outline POV-Ray closes.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.2,1.3,-6.9> look_at <0,0.5,0> angle 50 }
light_source { <-5,9,-6> rgb 1 }
plane { y, -1.01 pigment { rgb 0.7 } }
polygon { 28, <0, 0> <1, 0> <0, 1> <0, 0> <.3, .7> <.4, .7> <.3, .8> <.3, .7> <.5, .5> <.6, .5> <.5, .6> <.5, .5> <.7, .3> <.8, .3> <.7, .4> <.7, .3> <.5, .2> <.6, .2> <.5, .3> <.5, .2> <.2, .5> <.3, .5> <.2, .6> <.2, .5> <.1, .1> <.2, .1> <.1, .2> <.1, .1>
  scale 2.6 translate <-2.9,-0.6,0> rotate x*20 pigment { rgb <1,0.8,0.2> } }
polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1,0>, <0, 0>, <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4>
  scale 0.43 translate <0.4,-0.9,0> rotate <50,20,0> pigment { rgb <0.5,0.8,1> } }
polygon { 5, <-1,-1,0.5>, <1,-1,0.5>, <1.3,1.4,0.5>, <0,2.2,0.5>, <-1.1,1.4,0.5> translate <2.7,0.3,0> rotate y*-25 pigment { rgb <0.9,0.4,0.7> } }
