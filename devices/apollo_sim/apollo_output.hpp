#pragma once
// "RowSource18 -> Apollo screen -> PNG" in one call, for `lattice render
// --device apollo` and `lattice quantize`-style tools: quantize to the
// profile's colour map size, draw through GPR, save the screen through its
// colour map as a palette PNG (written atomically).
#include <filesystem>

#include "devices/apollo_sim/apollo_profile.hpp"
#include "pipeline/indexed_image.hpp"
#include "pipeline/run_pipeline.hpp"

namespace lattice {

struct ApolloScreen {
  IndexedImage screen;  // the whole screen, colour map included
  PipelineReport report;
};

// Draws the source on a simulated display of the given profile.
ApolloScreen renderToApollo(RowSource18& source, const ApolloProfile& profile, const PipelineOptions& options);
// The same, then writes the screen to `png`; returns the pipeline report.
PipelineReport renderToApolloPng(RowSource18& source, const ApolloProfile& profile, const PipelineOptions& options,
                                 const std::filesystem::path& png);

}  // namespace lattice
