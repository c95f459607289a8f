// A function pattern's value wraps as gradient's does: values above 1 are reduced mod 1
// first, so 2 and 3 give 0 (not the top of the map), 2.5 gives 0.5 and 1 stays 1; negatives
// wrap by 1. Columns: 1, 1.5, 2, 2.5, 3.25, -0.3, -2.5, 0.999.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> direction z right x up y }
#declare V = array[8] { 1, 1.5, 2, 2.5, 3.25, -0.3, -2.5, 0.999 }
#declare I = 0;
#while (I < 8)
box { <I/8, 0, 0>, <(I+1)/8, 1, 1> pigment { function { V[I] } color_map { [0 rgb <0, 0, 1>] [1 rgb <1, 0.5, 0>] } }
  finish { ambient 1 diffuse 0 } }
#declare I = I + 1;
#end
