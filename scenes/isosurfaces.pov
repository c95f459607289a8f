#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

// isosurfaces.pov -- lancer example scene
//
// Four isosurfaces on a checker floor: a scaled one cut by its closed
// sphere container, a glass ball (refraction and reflection rays leave
// points that lie up to one accuracy inside the surface), a rippled sheet
// with a ball subtracted (CSG needs all_intersections) and a wobbly ball
// whose max_gradient comes from evaluate.
//
// References: reference/isosurfaces*.png, 320x240, rendered by
// scripts/make_references.sh.

camera { location <0,3,-8> look_at 0 angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
plane { y, -1.2 pigment { checker rgb 1 rgb 0.3 } }

isosurface {
  function { x*x + z*z - 0.3 + 0.2*sin(3*y) }
  contained_by { sphere { 0, 1 } }
  max_gradient 3
  pigment { rgb <1,0.5,0.2> } finish { phong 0.5 }
  scale <1.2,0.8,1> translate <-2.5,0,0>
}

isosurface {
  function { sqrt(x*x+y*y+z*z) - 0.8 }
  accuracy 0.0005
  pigment { rgbf <1,1,1,0.9> } finish { reflection 0.1 }
  interior { ior 1.5 }
}

difference {
  isosurface {
    function { y - 0.3*sin(4*x) }
    contained_by { box { <-1,-1,-1>, <1,0.8,1> } }
    all_intersections
    max_gradient 2
  }
  sphere { <0,0.3,-1>, 0.6 }
  pigment { rgb <0.3,0.8,0.3> }
  translate <2.5,0,0>
}

isosurface {
  function { sqrt(x*x+y*y+z*z) + 0.3*sin(6*x) }
  threshold 0.8
  evaluate 1, 1.5, 0.7
  contained_by { box { -1.5, 1.5 } }
  pigment { rgb <0.5,0.5,1> }
  scale 0.7 translate <0,0,3.5>
}
