#pragma once
// The quantizer's settings, each declared once: the palette size, dithering,
// the split rule, refinement, the pipeline mode, the sample step and the
// histogram's form. The command-line flags of `render`, `quantize` and
// `bake`, their help and docs/cli.md's table are read from this table
// (app/cli/pipeline_args.hpp, tests/devices/shared/settings_doc_test.cpp),
// and every value goes through the one number parser, so NaN and values out
// of range are refused once.
#include "foundation/settings_schema.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::quantize {

// initial(): the options before any flag, the defaults the docs give (a
// palette of at most 256 colours, two passes, no dithering).
const SettingsSchema<PipelineOptions>& pipelineSettings();

}  // namespace lattice::quantize
