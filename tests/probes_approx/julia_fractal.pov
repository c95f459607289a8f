// julia_fractal with p = 0, where povray's rules show plainly: quaternion (the unit sphere,
// shrunk by a low precision), hypercomplex sqr after max_iteration - 1 squarings (escape at
// |h| > 4), and a sliced hypercomplex sqr.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-9> look_at 0 angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
julia_fractal { <0,0,0,0> quaternion sqr max_iteration 4 precision 2 pigment { rgb <1,0.5,0.2> } finish { phong 0.6 } translate <-2.6,1.2,0> }
julia_fractal { <0,0,0,0> quaternion cube max_iteration 3 precision 50 pigment { rgb <0.3,0.9,0.3> } translate <0,1.2,0> }
julia_fractal { <0,0,0,0> hypercomplex sqr max_iteration 3 precision 50 pigment { rgb <0.4,0.4,1> } rotate <20,30,0> translate <2.6,1.2,0> }
julia_fractal { <0,0,0,0> hypercomplex sqr max_iteration 3 precision 50 slice <0,0,0.3,1>, 0.2 pigment { rgb 1 } rotate <-20,30,0> translate <-1.5,-1.6,0> }
