#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare T1 = texture { pigment { rgb <0.9,0.3,0.1> } finish { ambient 0.2 diffuse 0.7 phong 0.6 } }
#declare T2 = texture { pigment { rgb <0.1,0.4,0.9> } finish { ambient 0.4 diffuse 0.5 } }
box { <-2.2,0.05,0>, <-0.05,1.7,1> texture { checker texture { T1 } texture { T2 } scale 0.4 } }
box { <0.05,0.05,0>, <2.2,1.7,1>
  texture { gradient x texture_map { [0.2 pigment { rgb 1 } finish { ambient 0.3 diffuse 0.6 }]
                                     [0.8 pigment { checker rgb 0, rgb <1,1,0> scale 0.2 } finish { ambient 0.3 diffuse 0.6 }] }
            scale 1.5 } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> texture { hexagon texture { T1 }, texture { T2 }, texture { pigment { rgb 0.8 } } scale 0.3 rotate x*90 } }
sphere { <1.1,-0.9,0>, 0.85 texture { tiles { texture { T2 } tile2 texture { T1 } } scale 0.5 } }
