// A union whose members are all no_shadow casts no shadow; a union with one shadow-casting
// member, a merge or an intersection of no_shadow members does (measured with povray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 30, -47> direction <0, 0, 3.0> right x*1.33 look_at 3*y }
light_source {<-50, 50, -1000> color rgb 0.75}
background { rgb 0.3 }
#declare Thing = box {-1, 1 scale <1, 2, 1> translate y * 2 }
union {
object { Thing pigment { rgb 0.7 } translate <0 1 -8> no_shadow }
object { Thing pigment { rgb 0.7 } translate <4 1 -8> }
object { Thing pigment { rgb 0.7 } translate <0 1 4> }
object { Thing pigment { rgb 0.7 } translate <4 1 4> }
}
union { box { <-8, 0, -9>, <-4, 4, -7> no_shadow } sphere { <-6, 2, -8>, 2.5 no_shadow } pigment { rgb 0.7 } }
box { <-7, 1, 4>, <-5, 5, 6> pigment { rgb 0.7 } }
merge { box { <5, 0, -9>, <8, 4, -7> no_shadow } sphere { <6.5, 2, -8>, 2 no_shadow } pigment { rgb 0.7 } }
intersection { box { <-12, 0, -9>, <-9, 4, -7> no_shadow } sphere { <-10.5, 2, -8>, 2 no_shadow } pigment { rgb 0.7 } }
