#version 3.7;
global_settings { assumed_gamma 1.0 }

// icospheres.pov -- lancer example scene
//
// Three icospheres built entirely in SDL: an icosahedron whose 20 faces are
// split recursively, each new vertex pushed back onto the unit sphere with
// vnormalize().  Subdivision 1, 3 and 5 (80, 1280 and 20480 flat
// triangles), left to right, so the faceting fades out.
//
// References: reference/icospheres.png (-A) and icospheres_aa.png (+A0.3), 320x240,
// rendered by scripts/make_references.sh.

camera {
  location <0, 2.8, -9.5>
  look_at  <0, 0.9, 0>
  angle 45
  right x*image_width/image_height
}

light_source { <-7, 10, -6> color rgb <1, 0.97, 0.92> }
light_source { <6, 4, -9> color rgb <0.28, 0.30, 0.36> shadowless }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0.0 color rgb <0.85, 0.85, 0.80>]
      [0.5 color rgb <0.85, 0.85, 0.80>]
      [1.0 color rgb <0.30, 0.40, 0.60>]
    }
    scale 2
    translate -y
  }
}

plane {
  y, 0
  pigment {
    checker color rgb <0.80, 0.78, 0.72> color rgb <0.55, 0.60, 0.62>
    scale 0.8
  }
  finish { ambient 0.06 diffuse 0.8 reflection 0.05 }
}

// --- icosphere construction ---

// Emit the triangles of the spherical triangle A B C (unit vectors),
// split Depth more times.
#macro Ico_Split(A, B, C, Depth)
  #if (Depth <= 0)
    triangle { A, B, C }
  #else
    #local AB = vnormalize(A + B);
    #local BC = vnormalize(B + C);
    #local CA = vnormalize(C + A);
    Ico_Split(A, AB, CA, Depth - 1)
    Ico_Split(AB, B, BC, Depth - 1)
    Ico_Split(CA, BC, C, Depth - 1)
    Ico_Split(AB, BC, CA, Depth - 1)
  #end
#end

// The 12 vertices of the unit icosahedron.
#declare Phi = (1 + sqrt(5)) / 2;
#declare IV0  = vnormalize(<-1,  Phi,  0>);
#declare IV1  = vnormalize(< 1,  Phi,  0>);
#declare IV2  = vnormalize(<-1, -Phi,  0>);
#declare IV3  = vnormalize(< 1, -Phi,  0>);
#declare IV4  = vnormalize(< 0, -1,  Phi>);
#declare IV5  = vnormalize(< 0,  1,  Phi>);
#declare IV6  = vnormalize(< 0, -1, -Phi>);
#declare IV7  = vnormalize(< 0,  1, -Phi>);
#declare IV8  = vnormalize(< Phi, 0, -1>);
#declare IV9  = vnormalize(< Phi, 0,  1>);
#declare IV10 = vnormalize(<-Phi, 0, -1>);
#declare IV11 = vnormalize(<-Phi, 0,  1>);

// A mesh of the unit icosphere with the given subdivision level:
// the 20 faces of the icosahedron, each handed to Ico_Split.
#macro Icosphere(Depth)
  mesh {
    Ico_Split(IV0,  IV11, IV5,  Depth)
    Ico_Split(IV0,  IV5,  IV1,  Depth)
    Ico_Split(IV0,  IV1,  IV7,  Depth)
    Ico_Split(IV0,  IV7,  IV10, Depth)
    Ico_Split(IV0,  IV10, IV11, Depth)
    Ico_Split(IV1,  IV5,  IV9,  Depth)
    Ico_Split(IV5,  IV11, IV4,  Depth)
    Ico_Split(IV11, IV10, IV2,  Depth)
    Ico_Split(IV10, IV7,  IV6,  Depth)
    Ico_Split(IV7,  IV1,  IV8,  Depth)
    Ico_Split(IV3,  IV9,  IV4,  Depth)
    Ico_Split(IV3,  IV4,  IV2,  Depth)
    Ico_Split(IV3,  IV2,  IV6,  Depth)
    Ico_Split(IV3,  IV6,  IV8,  Depth)
    Ico_Split(IV3,  IV8,  IV9,  Depth)
    Ico_Split(IV4,  IV9,  IV5,  Depth)
    Ico_Split(IV2,  IV4,  IV11, Depth)
    Ico_Split(IV6,  IV2,  IV10, Depth)
    Ico_Split(IV8,  IV6,  IV7,  Depth)
    Ico_Split(IV9,  IV8,  IV1,  Depth)
  }
#end

#declare Ico_Finish = finish { ambient 0.08 diffuse 0.75 specular 0.5 roughness 0.02 }

object {
  Icosphere(1)
  pigment { color rgb <0.90, 0.30, 0.15> }
  finish { Ico_Finish }
  rotate y*20
  translate <-2.6, 1, 0>
}
object {
  Icosphere(3)
  pigment { color rgb <0.95, 0.75, 0.15> }
  finish { Ico_Finish }
  rotate y*20
  translate <0, 1, 0>
}
object {
  Icosphere(5)
  pigment { color rgb <0.20, 0.50, 0.90> }
  finish { Ico_Finish }
  rotate y*20
  translate <2.6, 1, 0>
}
