// Radiosity probe: open box, gray.
#declare Rad_Gray = 1;
#include "open_box.inc"
