#include "devices/apollo_sim/apollo_output.hpp"

#include "devices/apollo_sim/apollo_sink.hpp"
#include "devices/apollo_sim/gpr_display.hpp"

namespace lattice {

ApolloScreen renderToApollo(RowSource18& source, const ApolloProfile& profile, const PipelineOptions& options) {
  GprDisplay display;
  display.init(GprDisplayMode::Borrow, profile);
  ApolloSink sink(display);
  ApolloScreen result;
  result.report = runPipeline(source, sink, options);
  result.screen = display.snapshot();
  display.terminate();
  return result;
}

}  // namespace lattice
