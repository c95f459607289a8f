// Radiosity probe: open box, base.

#include "open_box.inc"
