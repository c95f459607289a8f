// Radiosity probe: the open box seen through a mesh_camera (distribution 0, a face per pixel
// of a 48x36 picture, rays along the faces' normals into the box). The final trace's samples
// must serve one camera position only here too: the picture is the same for any thread count.

// Few gathering rays: the test is about which samples a pixel may use, not their quality.
#declare Rad_Count = 20;
#include "open_box.inc"
#declare Faces = mesh {
  #for (row, 0, 35)
    #for (col, 0, 47)
      triangle { <col, -row, 0>, <col + 0.1, -row + 0.1, 0>, <col + 0.1, -row, 0> }
    #end
  #end
}
camera { mesh_camera { 1 0 mesh { Faces scale 0.07 translate <-1.68, 2.2, -1.9> } } }
