// Radiosity probe: open box, the walls followed by a quarter of the gathering rays that meet
// them (radiosity { importance 0.25 }), the rest counting for them.
#declare Rad_Importance = 0.25;
#include "open_box.inc"
