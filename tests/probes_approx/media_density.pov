// Media with varying density: a spherical density with a colour map, a density_map of two
// patterns, and a crackle sheet density multiplied by a spherical one (adaptive sampling,
// aa_level 4). lancer samples steps evenly and halves those whose ends differ by more than
// aa_threshold; povray's adaptive rule is not measured exactly, so this is approximate.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -9> look_at 0 angle 50 }
background { rgb <0.05, 0.05, 0.1> }
sphere { 0, 1 hollow pigment { rgbt 1 }
  interior { media { emission 1.5 density { spherical color_map { [0 rgb 0] [0.5 rgb <1, 0.5, 0.1>] [1 rgb 1] } } } }
  translate -2.2*x }
sphere { 0, 1 hollow pigment { rgbt 1 }
  interior { media { emission <0.3, 0.8, 1.2> samples 9
    density { gradient y density_map { [0 rgb 0] [0.5 spherical] [1 rgb 0.2] } translate -y*0.5 } } } }
box { -1, 1 hollow pigment { rgbt 1 } translate 2.2*x
  interior { media { emission <1.5, 1.5, 0.3> samples 16 aa_level 4
    density { crackle scale 0.6 color_map { [0 rgb 0] [0.03 rgb 1] [0.06 rgb 0] [1 rgb 0] } }
    density { spherical scale 1.5 } } } }
