#version 3.7;
global_settings { assumed_gamma 1.0 }

// phong.pov -- lancer example scene
//
// The parts of the classic lighting model, one per sphere, left to right:
//   1. ambient only   (flat, unlit colour)
//   2. diffuse only   (Lambert shading, no highlight)
//   3. phong only     (black ball with just the highlight)
//   4. all three together
// A second light, lower and to the right, gives every highlight a twin.
//
// References: reference/phong.png (-A) and phong_aa.png (+A0.3), 320x240,
// rendered by scripts/make_references.sh.

// Named greys, declared here rather than taken from colors.inc so the scene (and lancer's
// tests) need nothing but this directory.
#declare White  = rgb 1;
#declare Gray30 = White * 0.30;
#declare Gray50 = White * 0.50;
#declare Gray80 = White * 0.80;

camera {
  location <0, 2.6, -12>
  look_at  <0, 0.9, 0>
  angle 46
  right x*image_width/image_height
}

light_source { <-6, 8, -8> color White }
light_source { <8, 2, -6> color Gray30 }

background { color rgb <0.04, 0.05, 0.08> }

// a floor and a back wall
plane {
  y, 0
  pigment { checker color Gray50 color Gray80 scale 1.5 }
  finish { ambient 0.05 diffuse 0.7 }
}
plane {
  -z, -6
  pigment {
    gradient y
    color_map {
      [0.0 color rgb <0.45, 0.50, 0.60>]
      [1.0 color rgb <0.10, 0.12, 0.20>]
    }
    scale 6
  }
  finish { ambient 0.1 diffuse 0.6 }
}

#declare Base = rgb <0.85, 0.30, 0.10>;

#macro Ball(X, Fin)
  sphere {
    <X, 1, 0>, 1
    pigment { color Base }
    finish { Fin }
  }
#end

#declare Ambient_Only = finish { ambient 0.8 diffuse 0 }
#declare Diffuse_Only = finish { ambient 0 diffuse 0.9 }
#declare Phong_Only   = finish { ambient 0 diffuse 0 phong 1 phong_size 40 }
#declare All_Three    = finish { ambient 0.12 diffuse 0.75 phong 0.9 phong_size 40 }

Ball(-3.3, Ambient_Only)
Ball(-1.1, Diffuse_Only)
Ball( 1.1, Phong_Only)
Ball( 3.3, All_Three)
