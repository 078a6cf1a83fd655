// scenes/thesis-camera.toml in POV-Ray 3.7 SDL, for bench/povray-peer.sh.
// Render: povray -D -A +FN8 File_Gamma=1.0 +W256 +H256 thesis-camera.pov
// The light falloff, materials and linear output are matched as explained at
// the top of sphere-hole.pov and in docs/benchmarks.md.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.15 max_trace_level 1 }
background { rgb <0, 0, 0> }

// The thesis camera (eq. 1.2): observer at (0, 0, -D), D = 2, a W x H = 1 x 1
// display whose CORNER pixels' centres lie on the display's corners, so the
// pixel pitch is W / (Nx - 1). POV's pitch is |right| / Nx with pixel centres
// symmetric about the direction, hence right = W Nx / (Nx - 1) = 256/255 and
// likewise up.
camera {
  perspective
  location <0, 0, -2>
  direction <0, 0, 2>
  right <256 / 255, 0, 0>
  up <0, 256 / 255, 0>
}

// K = 1: fade_distance 1 and colour I_inc / 2 give I_inc / (D + 1) exactly.
light_source { <-3.0, 4.0, 0.0> rgb 8.0 / 2 fade_distance 1 fade_power 1 }
light_source { <4.0, 2.0, 1.0> rgb 3.0 / 2 fade_distance 1 fade_power 1 }

// [materials.blue]: ambient = diffuse = [0.3, 0.4, 0.9], specular 0.7, shininess 25
sphere { <0, 0, 4>, 1.0
  texture {
    pigment { rgb <0.3, 0.4, 0.9> }
    finish { ambient 1 diffuse 1 phong 0.7 phong_size 25 }
  }
}

// half_space normal [0, 1, 0], offset -1: the solid y < -1.
plane { <0, 1, 0>, -1.0
  // [materials.floor]: ambient = diffuse = [0.7, 0.7, 0.6]
  texture {
    pigment { rgb <0.7, 0.7, 0.6> }
    finish { ambient 1 diffuse 1 phong 0 }
  }
}
