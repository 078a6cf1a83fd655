#include "devices/apollo_sim/apollo_output.hpp"

#include "devices/apollo_sim/apollo_driver.hpp"
#include "devices/apollo_sim/gpr_display.hpp"

namespace lattice::apollo {

ApolloScreen renderToApollo(RowSource18& source, const ApolloProfile& profile, const quantize::PipelineOptions& options) {
  GprDisplay display;
  display.init(GprDisplayMode::Borrow, profile);
  ApolloDriver sink(display);
  ApolloScreen result;
  result.report = quantize::runPipeline(source, sink, options);
  result.screen = display.snapshot();
  display.terminate();
  return result;
}

}  // namespace lattice::apollo
