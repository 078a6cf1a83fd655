#pragma once
// "RowSource18 -> Apollo screen" in one call, for `lattice render --device
// apollo`: quantize to the profile's colour map size and draw through GPR. The
// caller saves the screen (a palette PNG in the CLI); devices write no files.
#include "devices/apollo_sim/apollo_profile.hpp"
#include "foundation/indexed_image.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::apollo {

struct ApolloScreen {
  IndexedImage screen;  // the whole screen, colour map included
  quantize::PipelineReport report;
};

// Draws the source on a simulated display of the given profile.
ApolloScreen renderToApollo(RowSource18& source, const ApolloProfile& profile, const quantize::PipelineOptions& options);

}  // namespace lattice::apollo
