// scenes/torus-floor.toml in POV-Ray 3.7 SDL, for bench/povray-peer.sh.
// Render: povray -D -A +FN8 File_Gamma=1.0 +W320 +H240 torus-floor.pov
// The light falloff, materials, linear output, camera and matrices are
// matched as explained at the top of sphere-hole.pov and in docs/benchmarks.md.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.2 max_trace_level 1 }
background { rgb <0.55, 0.65, 0.8> }

camera {
  perspective
  location <0.0, 2.6, -5.0>
  direction <0.000000000000, -0.461352736642, 0.887216801235>
  right <-0.918206968772, 0.000000000000, 0.000000000000>
  up <0.000000000000, 0.610986487279, 0.317712973385>
}

// [[lights]] position [3, 6, -3], intensity 7.5 (K = 0)
light_source { <3.0, 6.0, -3.0> rgb 7.5 / 2e-4 fade_distance 1e-4 fade_power 1 }
// [[lights]] position [-5, 3, -1], intensity [1.8, 1.4, 1.0]
light_source { <-5.0, 3.0, -1.0> rgb <1.8, 1.4, 1.0> / 2e-4 fade_distance 1e-4 fade_power 1 }

// Lattice's torus (major 1, minor 0.35) has its axis along z, POV's along y:
// the matrix is rotate-x 90 (POV's y axis onto z), then the scene's rotate-x
// 65 and rotate-y 20, then translate [0, 0.45, 0].
torus { 1.0, 0.35
  matrix <0.939692620786, 0.000000000000, -0.342020143326,
          0.144543958453, -0.906307787037, 0.397131261967,
          -0.309975519219, -0.422618261741, -0.851650739639,
          0, 0.45, 0>
  // [materials.gold]: ambient = diffuse = [0.9, 0.7, 0.25], specular 0.6, shininess 60
  texture {
    pigment { rgb <0.9, 0.7, 0.25> }
    finish { ambient 1 diffuse 1 phong 0.6 phong_size 60 }
  }
}

// type = "half_space", normal [0, 1, 0], offset -0.6: the solid y < -0.6,
// which is exactly POV's plane { y, -0.6 }.
plane { <0, 1, 0>, -0.6
  // [materials.floor]: ambient 0.6, diffuse 0.75 (grey), no specular
  texture {
    pigment { rgb 0.75 }
    finish { ambient 0.6 / 0.75 diffuse 1 phong 0 }
  }
}
