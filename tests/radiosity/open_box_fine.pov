// Radiosity probe: open box, finely sampled (400 rays a sample, error_bound 0.2, one bounce):
// little is left to the blending of samples, so the wall's level is the gathered light's.

#declare Rad_Count = 400;
#declare Rad_Error = 0.2;
#declare Rad_Recursion = 1;
#include "open_box.inc"
