// scenes/sphere-hole.toml in POV-Ray 3.7 SDL, for bench/povray-peer.sh.
// Render: povray -D -A +FN8 File_Gamma=1.0 +W256 +H256 sphere-hole.pov
// How each part of Lattice's model is matched (docs/benchmarks.md explains):
// * eq. 2.3's I_inc / (D + K) falloff: POV's fade_power 1 gives
//   2 / (1 + D / fade_distance) = 2 fd / (fd + D), so a light colour of
//   I_inc / (2 fd) with fd = K gives I_inc / (D + K) exactly; for K = 0 we use
//   fd = 1e-4 (a 1e-4 / D relative error, below 8-bit resolution).
// * k_amb I_amb: ambient_light = I_amb, pigment = k_diff, finish ambient =
//   k_amb / k_diff (here 1); Phong: phong = k_spec, phong_size = n_spec.
// * Linear output (no gamma anywhere): assumed_gamma 1 and File_Gamma=1.0.
// * Camera: Lattice's look-at camera written out as explicit vectors (no
//   look_at, so POV keeps them verbatim): direction = the unit forward
//   vector, right and up = the image plane's full width and height at
//   distance 1. POV 3.7 (without antialiasing) shoots through pixel centres
//   as Lattice does, so the pixels line up.
// * Transforms: the scene's rotations as one matrix (Rodrigues, same numbers
//   as render/scene_loader.cpp); POV's matrix rows are the images of x, y, z.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.25 max_trace_level 1 }
background { rgb <0.05, 0.06, 0.12> }

camera {
  perspective
  location <3.0, 2.2, 4.0>
  direction <-0.549189019454, -0.402738614266, -0.732252025938>
  right <0.458792617214, 0.000000000000, -0.344094462911>
  up <-0.138580127169, 0.524924724126, -0.184773502892>
}

// [[lights]] position [4, 6, 5], intensity 9.5 (K = 0)
light_source { <4.0, 6.0, 5.0> rgb 9.5 / 2e-4 fade_distance 1e-4 fade_power 1 }
// [[lights]] position [-5, 1, 3], intensity [2.0, 2.4, 3.0]
light_source { <-5.0, 1.0, 3.0> rgb <2.0, 2.4, 3.0> / 2e-4 fade_distance 1e-4 fade_power 1 }

// [materials.clay]: ambient = diffuse = [0.8, 0.45, 0.3], specular 0.5, shininess 40
#declare Clay = texture {
  pigment { rgb <0.8, 0.45, 0.3> }
  finish { ambient 1 diffuse 1 phong 0.5 phong_size 40 }
}

difference {
  sphere { <0, 0, 0>, 1.0 }
  // Lattice's cylinder is infinite along z; POV's is capped, so it is made
  // long enough (|z| <= 3) to pass right through the unit sphere.
  cylinder { <0, 0, -3>, <0, 0, 3>, 0.42
    // rotate x by -25 degrees, then y by 40 degrees
    matrix <0.766044443119, 0.000000000000, -0.642787609687,
            -0.271653782274, 0.906307787037, -0.323744370967,
            0.582563416070, 0.422618261741, 0.694272044015,
            0, 0, 0>
  }
  texture { Clay }
}
