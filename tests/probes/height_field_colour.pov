// Height fields from a colour TGA (red the high byte of the height, green the low one), a palette PNG (the index is the height) and a function whose values wrap around 0 and 1; the images were made with PIL.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5,1.4,-1.4> look_at <0.5,0.2,0.4> angle 60 }
light_source { <3,6,-4> rgb 1 }
background { rgb <0.2,0.3,0.5> }
height_field { tga "hf_rg.tga" pigment { rgb <0.9,0.5,0.4> } scale <0.48,0.3,0.48> }
height_field { png "hf_palette.png" pigment { rgb <0.4,0.8,0.9> } scale <0.48,0.3,0.48> translate x*0.52 }
height_field { function 30, 30 { x*1.6 - 0.3 } pigment { rgb 0.8 } scale <1,0.25,0.4> translate z*0.55 rotate -5*x }
