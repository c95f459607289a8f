#version 3.7;
global_settings { assumed_gamma 1.0 }

// mirror_spheres.pov -- lancer example scene
//
// A mirror sphere, a matte sphere and a glossy (phong) sphere on a
// checker floor, ringed by small coloured balls.  Two brightly coloured
// spheres sit BEHIND the camera: they are not in the camera's field of
// view and can only be seen reflected in the mirror sphere.
//
// References: reference/mirror_spheres.png (-A) and mirror_spheres_aa.png (+A0.3), 320x240,
// rendered by scripts/make_references.sh.

#declare CamPos = <0, 1.6, -5.6>;

camera {
  location CamPos
  look_at  <0, 0.9, 0>
  angle 55
  right x*image_width/image_height
}

light_source { <-6, 9, -7> color rgb <1, 0.97, 0.92> }
light_source { <7, 5, -3> color rgb <0.25, 0.28, 0.35> shadowless }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0.0 color rgb <0.75, 0.80, 0.90>]
      [0.5 color rgb <0.75, 0.80, 0.90>]
      [1.0 color rgb <0.15, 0.30, 0.65>]
    }
    scale 2
    translate -y
  }
}

// checker floor
plane {
  y, 0
  pigment { checker color rgb <0.85, 0.85, 0.80> color rgb <0.10, 0.12, 0.18> }
  finish { ambient 0.05 diffuse 0.8 reflection 0.08 }
}

// the mirror
sphere {
  <0, 1.2, 0.6>, 1.2
  pigment { color rgb <0.02, 0.02, 0.02> }
  finish {
    ambient 0 diffuse 0.05
    specular 0.9 roughness 0.002
    reflection 0.92
  }
}

// matte sphere
sphere {
  <-2.7, 0.75, 1.4>, 0.75
  pigment { color rgb <0.80, 0.18, 0.12> }
  finish { ambient 0.08 diffuse 0.85 }
}

// glossy (phong) sphere
sphere {
  <2.7, 0.8, 1.6>, 0.8
  pigment { color rgb <0.10, 0.25, 0.85> }
  finish { ambient 0.08 diffuse 0.7 phong 0.9 phong_size 60 }
}

// a ring of small balls around the mirror, made with #while
#declare Ring_Finish = finish { ambient 0.1 diffuse 0.75 phong 0.5 phong_size 40 }
#declare N = 12;
#declare I = 0;
#while (I < N)
  #declare A = 2 * pi * (I + 0.5) / N;
  #declare K = mod(I, 3);       // cycles through three colours
  #if (K = 0)
    #declare C = <1.0, 0.75, 0.1>;
  #else
    #if (K = 1)
      #declare C = <0.1, 0.75, 0.3>;
    #else
      #declare C = <0.9, 0.9, 0.95>;
    #end
  #end
  sphere {
    <1.95 * cos(A), 0.22, 0.6 + 1.95 * sin(A)>, 0.22
    pigment { color rgb C }
    finish { Ring_Finish }
  }
  #declare I = I + 1;
#end

// --- behind the camera: only visible in the mirror sphere ---
sphere {
  CamPos + <-2.5, 1.5, -6.0>, 3.0
  pigment { color rgb <1.0, 0.55, 0.0> }
  finish { ambient 0.35 diffuse 0.7 }
}
sphere {
  CamPos + <3.0, -0.2, -4.5>, 1.8
  pigment { color rgb <0.95, 0.05, 0.75> }
  finish { ambient 0.35 diffuse 0.7 }
}
