#version 3.7;
global_settings { assumed_gamma 1.0 }

// roughness.pov -- lancer example scene
//
// Six spheres in a row, from rough to polished: the specular highlight
// goes from broad and dull (roughness 0.5) to a tiny sharp glint
// (roughness 0.001), and the reflection grows from none to strong.
// Striped walls behind and around make the reflections easy to read.
//
// References: reference/roughness.png (-A) and roughness_aa.png (+A0.3), 320x240,
// rendered by scripts/make_references.sh.

camera {
  location <0, 1.5, -8>
  look_at  <0, 0.7, 0>
  angle 54
  right x*image_width/image_height
}

light_source { <-4, 7, -9> color rgb <1, 0.97, 0.92> }
light_source { <6, 3, -6> color rgb <0.22, 0.24, 0.30> }

background { color rgb <0.02, 0.02, 0.03> }

// floor
plane {
  y, 0
  pigment {
    checker color rgb <0.50, 0.49, 0.46> color rgb <0.12, 0.13, 0.15>
    scale 1.4
  }
  finish { ambient 0.05 diffuse 0.8 }
}

// back wall with coloured vertical stripes
plane {
  -z, -7
  pigment {
    gradient x
    color_map {
      [0.00 color rgb <0.45, 0.10, 0.07>]
      [0.25 color rgb <0.45, 0.10, 0.07>]
      [0.25 color rgb <0.55, 0.45, 0.15>]
      [0.50 color rgb <0.55, 0.45, 0.15>]
      [0.50 color rgb <0.10, 0.32, 0.18>]
      [0.75 color rgb <0.10, 0.32, 0.18>]
      [0.75 color rgb <0.12, 0.20, 0.45>]
      [1.00 color rgb <0.12, 0.20, 0.45>]
    }
    scale 4
  }
  finish { ambient 0.05 diffuse 0.45 }
}

// a wall behind the camera (seen only in reflections): light below, dark above
plane {
  z, -16
  pigment {
    gradient y
    color_map {
      [0.0 color rgb <0.45, 0.45, 0.42>]
      [1.0 color rgb <0.02, 0.02, 0.03>]
    }
    scale 8
  }
  finish { ambient 0.3 diffuse 0.5 }
}

// the row of spheres: roughness falls geometrically from 0.5 to 0.001,
// reflection rises from 0 to 0.6
#declare N = 6;
#declare R_Start = 0.5;
#declare R_End = 0.001;
#declare Spacing = 1.3;
#declare I = 0;
#while (I < N)
  #declare T = I / (N - 1);
  #declare Rough = R_Start * pow(R_End / R_Start, T);
  #declare Refl = 0.6 * T * T;
  sphere {
    <(I - (N - 1) / 2) * Spacing, 0.55, 0>, 0.55
    pigment { color rgb <0.40, 0.04, 0.03> }
    finish {
      ambient 0.05
      diffuse 0.65 * (1 - 0.5 * T)
      specular 0.7
      roughness Rough
      reflection Refl
    }
  }
  // a small disc under each sphere, like a coaster
  disc {
    <(I - (N - 1) / 2) * Spacing, 0.005, 0>, y, 0.53
    pigment { color rgb <0.95, 0.93, 0.88> }
    finish { ambient 0.08 diffuse 0.8 }
  }
  #declare I = I + 1;
#end
