// Radiosity probe: open box, bright.
#declare Rad_Brightness = 2;
#include "open_box.inc"
