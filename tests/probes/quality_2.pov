// options: +Q2
// Quality 2: what POV-Ray 3.7 leaves out at this level (manual 3.2.8.3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,1.5,-5> look_at <0,0.5,0> angle 50 }
light_source { <4,6,-4> color rgb 1 }
background { color rgb <0.2,0.3,0.5> }
plane { y, 0 pigment { checker rgb 1 rgb <0.1,0.5,0.1> } finish { reflection 0.2 } }
sphere { <-1,1,0>, 1 pigment { color rgb <1,0.2,0.2> quick_color rgb <0,0,1> } finish { phong 0.8 } }
sphere { <1.2,0.8,-0.5>, 0.8 pigment { color rgbt <0.8,0.9,1,0.7> } finish { reflection 0.3 } interior { ior 1.5 } }
sphere { <0.2,0.4,-1.8>, 0.4 pigment { checker rgb <1,1,0> rgb <0,1,1> scale 0.2 } finish { ambient 0.3 } }
