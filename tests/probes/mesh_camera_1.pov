// mesh_camera distribution 1: two meshes of half the pixels' faces each. Distribution 2
// 2 (mesh_camera_2.pov) puts them side by side;
// this probe is distribution 1, which sums the meshes.
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
camera { mesh_camera { 1 1 mesh { Half } mesh { Half translate <image_width / 2, 0, 0> } } }
plane { -z, -1
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb 0] [1 rgb <2, 0, 0>] } scale image_width]
    [1 gradient y color_map { [0 rgb 0] [1 rgb <0, 2, 0>] } scale image_height] } }
  finish { ambient 1 diffuse 0 } }
