#pragma once
// What the firmware renders: a scene baked on the host by `lattice bake`
// (app/scene_bake.hpp), compiled into the image as code and constant data.
// The generated file defines bakedScene(); nothing is parsed on the MCU.
#include <string>
#include <vector>

#include "quantize/run_pipeline.hpp"
#include "render/scene/scene.hpp"

namespace lattice::firmware {

struct BakedScene {
  std::string name;
  SceneDesc scene;
  int width = 0, height = 0;
  std::vector<std::string> settings;  // Tek 4125 profile overrides (key=value)
  quantize::PipelineOptions pipeline;
};

BakedScene bakedScene();

}  // namespace lattice::firmware
