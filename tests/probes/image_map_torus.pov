// image_map map_type 5 (torus): u around y as the cylindrical map, v around the tube (0.5 on
// the outer equator, growing upwards, the seam on the inner rim); scripts/measure_map_type.sh.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-6> look_at 0 angle 40 }
light_source { <-5,8,-10> rgb 1 }
torus { 1, 0.45 pigment { image_map { png "pattern_image.png" map_type 5 interpolate 2 } } finish { ambient 0.4 diffuse 0.6 } rotate 20*y }
