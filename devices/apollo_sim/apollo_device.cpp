#include "devices/apollo_sim/apollo_device.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "devices/apollo_sim/apollo_driver.hpp"
#include "devices/apollo_sim/apollo_profile.hpp"
#include "devices/apollo_sim/gpr_journal.hpp"
#include "foundation/error.hpp"

namespace lattice::apollo {
namespace {

// The driver draws through GPR calls that the journal turns into bytes.
class JournalDriver final : public devices::Driver {
 public:
  JournalDriver(ByteSink& out, const ApolloProfile& profile) : out_(out), journal_(out, profile), driver_(journal_) {}
  IndexedSink& sink() override { return driver_; }
  devices::DriverStats stats() const override {
    return {out_.bytesWritten(), 0.0, "GPR calls to the simulated display"};
  }

 private:
  ByteSink& out_;
  GprJournalWriter journal_;
  ApolloDriver driver_;
};

}  // namespace

devices::Device makeDevice(const std::vector<std::string>& settings) {
  ApolloProfile profile = apolloSettings().initial();
  applyOverrides(profile, settings);
  devices::Device d;
  d.name = "apollo";
  d.title = profile.model;
  d.width = profile.width;
  d.height = profile.height;
  d.makeDriver = [profile](ByteSink& out) { return std::make_unique<JournalDriver>(out, profile); };
  d.makeEmulator = [profile] { return std::unique_ptr<StreamDecoder>(std::make_unique<GprJournalDecoder>(profile)); };
  d.driverMemory = [](int, int) { return std::uint64_t{0}; };  // a row of pixel values at a time
  // The display's bitmap, a byte a pixel, then the screen as RGB for the PNG.
  d.emulatorMemory = 4 * static_cast<std::uint64_t>(profile.width) * static_cast<std::uint64_t>(profile.height);
  d.profileText = describe(profile);
  // The journal's header (gpr_journal.hpp).
  d.recognise = [](std::span<const std::uint8_t> head) {
    return head.size() >= sizeof kGprJournalHeader &&
           std::equal(std::begin(kGprJournalHeader), std::end(kGprJournalHeader), head.begin());
  };
  return d;
}

}  // namespace lattice::apollo
