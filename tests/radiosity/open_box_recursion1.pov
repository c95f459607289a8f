// Radiosity probe: open box, recursion1.
#declare Rad_Recursion = 1;
#include "open_box.inc"
