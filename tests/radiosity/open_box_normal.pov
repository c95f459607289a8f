// Radiosity probe: open box, normal.
#declare Rad_Normal = on;
#include "open_box.inc"
