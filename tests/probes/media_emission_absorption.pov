// Media: emission and absorption in constant density. povray 3.7 samples `samples 5` as three
// equal steps, each step's emission dimmed by the steps before it; absorption alone is
// exactly exp(-a*d). Boxes of depth 1, 2 and 3 over a checker.
// An interior with two media samples both by the first one's settings (bottom right).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x*8 up y*6 }
plane { z, 4 pigment { checker rgb 1, rgb <0.2, 0.4, 0.6> } finish { ambient 1 diffuse 0 } hollow }
#macro Slab(X, Y, D, I)
  box { <X - 1, Y - 1, 0>, <X + 1, Y + 1, D> hollow pigment { rgbt 1 }
    finish { ambient 0 diffuse 0 } interior { I } }
#end
#declare Glow = media { emission <0.4, 0.2, 0.1> absorption <0.2, 0.6, 1.0> samples 5 }
#declare Dark = media { absorption <1, 0.5, 0.2> }
#declare G = interior { media { Glow } }
#declare K = interior { media { Dark } }
Slab(-2.5, 1.5, 1, G) Slab(0, 1.5, 2, G) Slab(2.5, 1.5, 3, G)
Slab(-2.5, -1.5, 1, K) Slab(0, -1.5, 2, K)
Slab(2.5, -1.5, 3, interior { media { Glow } media { Dark } })
