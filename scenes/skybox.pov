#version 3.7;
global_settings { assumed_gamma 1.0 }

// skybox.pov -- lancer example scene
//
// An equirectangular panorama (sky.png, written by scripts/make_skybox.py)
// wrapped around the whole scene with a sky_sphere and image_map
// map_type 1 (spherical).  A mirror ball (left) reflects the panorama, a
// glass ball (right) shows it refracted upside down.  A postcard between
// them shows the same picture flat (image_map map_type 0, planar).
//
// Orientation of map_type 1 (checked against POV-Ray 3.7): the direction d
// maps to u = atan2(d.z, d.x) / 2pi (wrapped into [0,1)), v = 0.5 + asin(d.y)/pi;
// the left edge of the image is +x, a quarter of the way in is +z
// (straight ahead here: the striped tower), the top row is +y.
//
// References: reference/skybox.png (-A) and skybox_aa.png (+A0.3), 320x240,
// rendered by scripts/make_references.sh.

camera {
  location <0, 0.1, -5.6>
  look_at  <0, 0.45, 0>
  angle 60
  right x*image_width/image_height
}

sky_sphere {
  pigment { image_map { png "sky.png" map_type 1 } }
}

// The sun in sky.png is at azimuth 115 deg, elevation 22 deg: put the
// light there, far away, so highlights match the picture.
#declare Sun_Az = radians(115);
#declare Sun_El = radians(22);
light_source {
  1000 * <cos(Sun_El) * cos(Sun_Az), sin(Sun_El), cos(Sun_El) * sin(Sun_Az)>
  color rgb <1, 0.96, 0.88>
}
light_source { <3, 2, -8> color rgb 0.25 shadowless }

// pedestal: a short column with a groove cut round it
#declare Pedestal = difference {
  cylinder { <0, -1.8, 0>, <0, -1.0, 0>, 0.55 }
  torus { 0.58, 0.08 translate -1.4*y }
  pigment { color rgb <0.85, 0.82, 0.76> }
  finish { ambient 0.1 diffuse 0.75 specular 0.3 roughness 0.05 }
}

// the mirror ball
union {
  sphere {
    <0, 0, 0>, 1
    pigment { color rgb 0.02 }
    finish { ambient 0 diffuse 0.03 specular 1 roughness 0.001 reflection 0.95 }
  }
  object { Pedestal }
  translate <-1.35, 0, 0>
}

// the glass ball
union {
  sphere {
    <0, 0, 0>, 1
    pigment { color rgbf <0.98, 1.0, 0.99, 0.95> }
    finish {
      ambient 0 diffuse 0
      specular 0.8 roughness 0.001
      reflection { 0.0, 1.0 fresnel on }
      conserve_energy
    }
    interior { ior 1.474 }
  }
  object { Pedestal }
  translate <1.35, 0, 0>
}

// postcard: the panorama again, flat (planar map, 2:1 like the image)
box {
  <0, 0, 0>, <1, 1, 0.02>
  pigment { image_map { png "sky.png" map_type 0 } }
  finish { ambient 0.25 diffuse 0.7 }
  translate <-0.5, -0.5, 0>
  scale <1.1, 0.55, 1>
  rotate x*10
  translate <0, -1.25, -0.6>
}
