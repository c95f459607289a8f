// Height fields from GIFs: the palette index is the height, an interlaced GIF's rows are taken in file order as povray does, and a POT file (a GIF twice as wide, high bytes left, low bytes right) gives 16-bit heights, smooth; the images were made with PIL.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5,1.4,-1.4> look_at <0.5,0.2,0.4> angle 60 }
light_source { <3,6,-4> rgb 1 }
background { rgb <0.2,0.3,0.5> }
height_field { gif "hf_interlaced.gif" pigment { rgb <0.9,0.5,0.4> } scale <0.48,0.3,0.48> }
height_field { pot "hf_pot.gif" smooth pigment { rgb <0.4,0.8,0.9> } scale <0.48,0.3,0.48> translate x*0.52 }
