#version 3.7;
global_settings { assumed_gamma 1.0 }
// text in CSG: a block with crystal.ttf letters cut out (difference), a timrom "O" cut by a
// sphere (intersection), and povlogo through `internal 0`; string built with concat/str/chr.
camera { location <0,2.2,-3.4> look_at <0,0,0> angle 55 }
light_source { <-3,8,-5> rgb 1 }
background { rgb 0.15 }
difference {
  box { <-1.6,-0.45,-0.2>, <1.6,0.45,0.25> }
  text { ttf "crystal" concat("T", str(3.7,0,1), chr(33)) 0.3, 0 scale 1.1 translate <-1.4,-0.3,-0.3> }
  rotate x*50 translate z*0.3
  pigment { rgb <0.8,0.7,0.4> }
}
intersection {
  text { ttf "timrom.ttf" "O" 1, 0 translate <-0.35,-0.33,-0.5> }
  sphere { 0, 0.42 }
  pigment { rgb <0.2,0.7,0.6> } rotate y*40 translate <-1.1,-0.8,-0.5>
}
text { internal 0 "P" 0.3, 0 scale 0.7 rotate y*-25 translate <0.9,-1.1,-0.6> pigment { rgb <0.3,0.3,0.9> } }
