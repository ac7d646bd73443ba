// POV-Ray 3.7 version of scenes/smoke_tank.json, for the side-by-side in docs/performance.md:
// ten green laser beams (cylinder lights) through a biconvex and a biconcave lens (ior 1.5168,
// N-BK7 at the d line) in smoke (Henyey-Greenstein scattering 0.12 per unit, g = 0.5), with
// media photons for the bent beams. lenslab's scene is right-handed; POV-Ray's is
// left-handed, so z is mirrored (the lenses lie in z = 0, the camera at z = -9.5 here).
// Render: povray bench/smoke_tank.pov +W480 +H270 +A0.0 -D +Osmoke_tank_povray.png

#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { count 600000 media 400 autostop 0 jitter 0.4 max_trace_level 10 }
}

camera {
  perspective
  location <0, 0, -9.5>
  look_at <0, 0, 0>
  right x * 16 / 9
  angle 71.4  // horizontal: lenslab's fov 44 is vertical, 2 atan(tan 22 * 16/9)
}

// lenslab's lasers carry 1 W over a disc of radius 0.025: an irradiance of 509 per unit area.
#declare Laser = rgb <0.05, 1, 0.1> * 509;
#macro laser(Y)
  light_source {
    <-5, Y, 0> color Laser
    cylinder point_at <0, Y, 0> radius 0.025 falloff 0.03 tightness 0
    media_interaction on media_attenuation on
    photons { refraction on reflection on }
  }
#end
laser(1.65) laser(1.4) laser(1.15) laser(0.9) laser(0.65)
laser(-0.65) laser(-0.9) laser(-1.15) laser(-1.4) laser(-1.65)

#declare Glass = material {
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5168 }
}

// Biconvex: front vertex x = -2.65 (R 3, centre at 0.35), back vertex -2.35 (R 3, centre
// at -5.35), 1.4 across.
intersection {
  sphere { <0.35, 1.15, 0>, 3 }
  sphere { <-5.35, 1.15, 0>, 3 }
  cylinder { <-3, 1.15, 0>, <-2, 1.15, 0>, 0.7 }
  material { Glass }
  photons { target refraction on reflection on collect off }
}
// Biconcave: vertices at -2.56 and -2.44 (0.12 thick), R 3 each side, 1.4 across.
difference {
  cylinder { <-2.65, -1.15, 0>, <-2.35, -1.15, 0>, 0.7 }
  sphere { <-5.56, -1.15, 0>, 3 }
  sphere { <0.56, -1.15, 0>, 3 }
  material { Glass }
  photons { target refraction on reflection on collect off }
}

// The screen the beams end on.
box {
  <4.2, -2.5, -2.5>, <4.25, 2.5, 2.5>
  texture { pigment { rgb 0.5 } finish { ambient 0 diffuse 1 } }
}

// The smoke: a hollow box holding everything, the camera included (lenslab's atmosphere).
box {
  <-12, -8, -12>, <12, 8, 12>
  hollow
  texture { pigment { rgbt 1 } }
  interior {
    media {
      method 3 intervals 1 samples 10 aa_level 3 aa_threshold 0.05
      scattering { 5, rgb 0.12 eccentricity 0.5 }
    }
  }
  photons { pass_through }
}

background { rgb <0.004, 0.004, 0.006> }
