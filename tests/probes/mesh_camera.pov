// mesh_camera distribution 0, two rays per pixel from two meshes (one face per pixel, in rows
// from the top): which face each pixel takes (povray: pixel rows 0 and 1 both take the first
// row of faces) and the average of the rays.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0, 0, 1> }
#declare Faces = mesh {
  #for (row, 0, image_height - 1)
    #for (col, 0, image_width - 1)
      triangle { <col, -row, 0>, <col + 0.1, -row + 0.1, 0>, <col + 0.1, -row, 0> }
    #end
  #end
}
camera { mesh_camera { 2 0 mesh { Faces } mesh { Faces translate <0.5, -0.5, 0> } } }
plane { -z, -1
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb 0] [1 rgb <2, 0, 0>] } scale image_width]
    [1 gradient y color_map { [0 rgb 0] [1 rgb <0, 2, 0>] } scale image_height] } }
  finish { ambient 1 diffuse 0 } }
