// The Apollo as a byte-stream device: the driver's GPR calls written as a
// journal and replayed by the emulator must give the very screen the calls
// give on the simulated display directly; bad journals never throw and are
// never buffered beyond a screen.
#include <catch2/catch.hpp>

#include <vector>

#include "devices/apollo_sim/apollo_output.hpp"
#include "devices/apollo_sim/gpr_journal.hpp"
#include "devices/device_table.hpp"
#include "devices/work_budget.hpp"
#include "foundation/error.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/quantize/test_sources.hpp"

using namespace lattice;
using namespace lattice::quantize;
using namespace lattice::apollo;
using lattice::testing::FunctionSource;

namespace {

FunctionSource gradient(int width, int height) {
  return FunctionSource(width, height, [](int x, int y) {
    return packColor18(static_cast<unsigned>(x % 64), static_cast<unsigned>(y % 64), static_cast<unsigned>((x + y) % 64));
  });
}

PipelineOptions quiet() {
  PipelineOptions options;
  options.progress = false;
  options.quantize.dither = Dither::FloydSteinberg;
  return options;
}

}  // namespace

TEST_CASE("the journal replayed by the emulator is the screen the display draws directly") {
  for (const char* profile : {"dn660", "dn660-4", "dn580"}) {
    INFO(profile);
    auto direct = gradient(200, 120);
    const ApolloScreen expected = renderToApollo(direct, apolloProfileByName(profile), quiet());

    const devices::Device device = devices::makeDevice("apollo", {std::string("profile=") + profile});
    MemorySink bytes;
    auto driver = device.makeDriver(bytes);
    auto journalled = gradient(200, 120);
    runPipeline(journalled, driver->sink(), quiet());
    auto emulator = device.makeEmulator();
    // Uneven chunks: records cut anywhere must decode the same.
    const std::vector<std::uint8_t>& stream = bytes.data();
    for (std::size_t at = 0, step = 1; at < stream.size(); at += step, step = step * 3 % 1021 + 1)
      emulator->feed(std::span<const std::uint8_t>(stream).subspan(at, std::min(step, stream.size() - at)));
    emulator->finish();
    CHECK(emulator->report().malformed == 0);
    CHECK(emulator->report().unknownCommands == 0);
    CHECK(emulator->image().pixels == expected.screen.pixels);
    CHECK(emulator->image().colormap == expected.screen.colormap);
    CHECK(driver->stats().bytes == stream.size());
  }
}

TEST_CASE("a journal window larger than the screen is skipped as it arrives, not buffered") {
  GprJournalDecoder decoder(dn660Profile());
  const std::vector<std::uint8_t> head = {'G', 'P', 'R', 1, 'A',
                                          'W', 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF};  // 65535 x 65535 at (0, 0)
  decoder.feed(head);
  std::vector<std::uint8_t> payload(1 << 20, 7);
  decoder.feed(payload);  // part of the refused window: dropped
  CHECK(decoder.report().malformed == 1);
  const std::vector<std::uint8_t> clear = {'K', 3};
  decoder.feed(clear);  // still inside the refused record's payload: skipped too
  decoder.finish();
  CHECK(decoder.report().malformed == 2);  // the record cut off by the end
  CHECK(decoder.image().at(0, 0) == 0);
}

TEST_CASE("garbage into the journal decoder is counted, never thrown") {
  GprJournalDecoder decoder(dn660Profile(4));
  std::vector<std::uint8_t> noise(100000);
  std::uint32_t state = 12345;
  for (std::uint8_t& b : noise) {
    state = state * 1103515245u + 12345u;
    b = static_cast<std::uint8_t>(state >> 24);
  }
  CHECK_NOTHROW(decoder.feed(noise));
  CHECK_NOTHROW(decoder.finish());
  CHECK(decoder.report().bytes == noise.size());
  CHECK(decoder.report().unknownCommands + decoder.report().malformed > 0);
}

TEST_CASE("GPR journal: two-byte clears are charged to the drawing budget") {
  // Each 'K' record clears 1024 x 1024 pixels: 1,024 fit in kPixelWorkBudget,
  // the next is refused.
  auto journal = [](int clears) {
    std::vector<std::uint8_t> bytes(std::begin(kGprJournalHeader), std::end(kGprJournalHeader));
    bytes.push_back('A');
    for (int i = 0; i < clears; ++i) bytes.insert(bytes.end(), {'K', static_cast<std::uint8_t>(i % 2)});
    return bytes;
  };
  {
    GprJournalDecoder decoder(dn660Profile());
    REQUIRE_NOTHROW(decodeBytes(decoder, journal(1024), "fits.gpr"));
    CHECK(decoder.report().pixelWork == kPixelWorkBudget);
  }
  GprJournalDecoder decoder(dn660Profile());
  CHECK_THROWS_WITH(decodeBytes(decoder, journal(1025), "clears.gpr"),
                    Catch::Contains("clears.gpr") && Catch::Contains("kPixelWorkBudget"));
}
