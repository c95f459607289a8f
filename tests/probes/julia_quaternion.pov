// Quaternion julia_fractals (objects/fractal1 and fractal3 parameters; cube is not exact yet): povray's inside test
// (bailout min(2, 1 + |c|)), its distance-estimate march that steps over thin bands at a low
// precision, and normals from max_iteration squarings (src/geom/julia.rs).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-6> look_at 0 right x*6.4 up y*4.8 }
light_source { <-20,30,-100> rgb 1 }
light_source { <200,300,-500> rgb 0.5 }
background { rgb <0.2,0.3,0.5> }
julia_fractal { <.49,.5,-.34,.1> quaternion max_iteration 7 precision 10 pigment { rgb <0.6,1,0.5> } finish { phong 0.6 } rotate <110,50,-60> translate <-1.6,0.8,0> }
julia_fractal { <-0.03,0.5,-0.2,-0.5> quaternion sqr max_iteration 6 precision 3 slice <0.2,0,0.1,1>, 0.1 pigment { rgb 1 } rotate y*90 translate <1.6,-0.8,0> }
