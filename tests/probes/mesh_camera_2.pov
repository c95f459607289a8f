// mesh_camera distributions 1 and 2: two meshes of half the pixels' faces each. Distribution 2
// puts them side by side (povray numbers a block's faces from the image's left edge);
// MESHCAM_DIST selects (1 sums the meshes, shooting one ray through each face in turn).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0, 0, 1> }
#declare Half = mesh {
  #for (row, 0, image_height - 1)
    #for (col, 0, image_width / 2 - 1)
      triangle { <col, -row, 0>, <col + 0.1, -row + 0.1, 0>, <col + 0.1, -row, 0> }
    #end
  #end
}
camera { mesh_camera { 1 2 mesh { Half } mesh { Half translate <image_width / 2, 0, 0> } } }
plane { -z, -1
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb 0] [1 rgb <2, 0, 0>] } scale image_width]
    [1 gradient y color_map { [0 rgb 0] [1 rgb <0, 2, 0>] } scale image_height] } }
  finish { ambient 1 diffuse 0 } }
