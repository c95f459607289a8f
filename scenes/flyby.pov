#version 3.7;
global_settings { assumed_gamma 1.0 }

// flyby.pov -- lancer's demo animation
//
// A camera flies once around a small still life along a natural spline, looking at a point
// that drifts across the table. Render all 48 frames with flyby.ini:
//
//   lancer scenes/flyby.ini              (writes flyby01.png ... flyby48.png)
//   scripts/flyby_gif.sh                 (renders, then joins the frames into flyby.gif)
//
// Only features lancer renders are used, so each frame can be checked against POV-Ray's.

// The path: eight points around the table at varying height, closed by repeating the first
// points so the natural spline's ends do not kink the loop.
#declare Path = spline {
  natural_spline
  -0.125, <-4.2, 1.2, -3.0>
   0.000, < 0.0, 1.8, -5.2>
   0.125, < 4.2, 2.4, -3.6>
   0.250, < 5.4, 1.5,  0.0>
   0.375, < 3.8, 2.8,  3.8>
   0.500, < 0.0, 3.4,  5.0>
   0.625, <-3.8, 2.2,  3.8>
   0.750, <-5.4, 1.4,  0.0>
   0.875, <-4.2, 1.2, -3.0>
   1.000, < 0.0, 1.8, -5.2>
   1.125, < 4.2, 2.4, -3.6>
}

#declare Target = <0.6 * sin(2 * pi * clock), 0.7, 0.4 * cos(2 * pi * clock)>;

camera {
  location Path(clock)
  look_at Target
  angle 50
  right x * image_width / image_height
}

light_source { <-6, 10, -6> color rgb <1, 0.96, 0.9> }
light_source { <6, 6, 4> color rgb <0.25, 0.27, 0.33> shadowless }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0.0 color rgb <0.80, 0.84, 0.92>]
      [1.0 color rgb <0.20, 0.35, 0.70>]
    }
  }
}

plane {
  y, 0
  pigment { checker color rgb <0.82, 0.80, 0.74> color rgb <0.16, 0.17, 0.22> scale 0.8 }
  finish { ambient 0.05 diffuse 0.8 reflection 0.06 }
}

// the table top
cylinder {
  <0, 0, 0>, <0, 0.25, 0>, 2.4
  pigment { color rgb <0.45, 0.30, 0.20> }
  finish { ambient 0.06 diffuse 0.75 phong 0.3 phong_size 30 }
}

// a mirror ball, a glass ball and a torus ring on the table
sphere {
  <-0.8, 0.95, 0.3>, 0.7
  pigment { color rgb 0.02 }
  finish { ambient 0 diffuse 0.05 specular 0.9 roughness 0.002 reflection 0.9 }
}

sphere {
  <0.9, 0.75, -0.4>, 0.5
  pigment { color rgbf <0.95, 1.0, 0.97, 0.9> }
  finish { ambient 0 diffuse 0.05 specular 0.8 roughness 0.003 reflection { 0.05, 1 fresnel } conserve_energy }
  interior { ior 1.5 }
}

torus {
  0.55, 0.12
  rotate x * 70
  translate <0.5, 0.8, 1.2>
  pigment { color rgb <0.85, 0.60, 0.10> }
  finish { ambient 0.08 diffuse 0.6 specular 0.6 roughness 0.02 metallic reflection 0.3 }
}

// a ring of small cones around the table, made with #for
#for (I, 0, 11)
  #local A = 2 * pi * I / 12;
  cone {
    <3.3 * cos(A), 0, 3.3 * sin(A)>, 0.25, <3.3 * cos(A), 0.9, 3.3 * sin(A)>, 0
    pigment { color rgb <0.2 + 0.6 * mod(I, 2), 0.35, 0.8 - 0.5 * mod(I, 2)> }
    finish { ambient 0.08 diffuse 0.75 phong 0.5 phong_size 40 }
  }
#end
