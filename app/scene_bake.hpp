#pragma once
// `lattice bake`'s work as a library call: a loaded scene, the picture size,
// the Tek 4125 settings and the quantizer options, written as one C++ file
// the firmware compiles (docs/firmware.md). The file defines
// lattice::firmware::bakedScene() (firmware/baked_scene.hpp), which rebuilds
// the SceneDesc in code: camera, lights, materials, options and the CSG tree
// with every leaf's own construction (LeafDesc::bake), the lattice tables'
// slots as constant arrays (flash). So the firmware has no parser, and the
// scene it renders is the host's to the last bit (numbers are hexadecimal
// floating literals).
#include <string>
#include <vector>

#include "loader/lattice_scene_loader.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {

struct BakeRequest {
  std::string sceneFile;              // for the header comment and the scene's name
  int width = 64, height = 64;
  std::vector<std::string> settings;  // the Tek 4125 profile's key=value overrides
  quantize::PipelineOptions pipeline;
};

struct BakeResult {
  std::string source;         // the C++ file
  std::size_t flashBytes = 0;  // bytes of the constant arrays (lattice tables)
  std::size_t leaves = 0;
};

// Throws lattice::Error(Usage) for a leaf that cannot be baked.
BakeResult bakeScene(const lht::SceneWithLattices& loaded, const BakeRequest& request);

}  // namespace lattice::app
