// What the first pair of `!RVE` does is not settled by any source: the font
// tool tekmkfnt.c starts its `!rve` with `0,0`, and its font preview reads
// as if the first pair moved the beam (as the first pair of `!VEC` does).
// The emulator takes either reading (profile key rve-first=move|draw). The
// driver starts every `!RVE` with `0 0`, so its streams draw the same
// picture under both; a stream whose `!RVE` starts with a step does not.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_encoder.hpp"
#include "tests/devices/tek4027/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::tek4027;
using namespace lattice::tek4027::test;
using lattice::testing::ringsImage;

namespace {

Tek4027Profile reading(Tek4027Profile profile, std::string_view firstPair) {
  applyOverride(profile, std::string("rve-first=") + std::string(firstPair));
  return profile;
}

IndexedImage decodeUnder(std::string_view text, const Tek4027Profile& profile) {
  Tek4027Decoder d(profile);
  d.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  d.finish();
  INFO(text.substr(0, 200));
  CHECK(d.report().malformed == 0);
  CHECK(d.report().unknownCommands == 0);
  return d.image();
}

// The arguments of each `!RVE` in a stream, as text tokens.
std::vector<std::vector<std::string>> rveArguments(const std::string& text, char commandChar = '!') {
  std::vector<std::vector<std::string>> out;
  for (std::size_t at = text.find(commandChar); at != std::string::npos; at = text.find(commandChar, at + 1)) {
    if (text.compare(at + 1, 3, "RVE") != 0) continue;
    const std::size_t end = std::min(text.find_first_of(std::string{commandChar, '\r', ';'}, at + 1), text.size());
    std::vector<std::string> args;
    std::string token;
    for (std::size_t i = at + 4; i <= end; ++i) {
      const char c = i < end ? text[i] : ' ';
      if (c == ' ' || c == ',') {
        if (!token.empty()) args.push_back(token);
        token.clear();
      } else {
        token += c;
      }
    }
    out.push_back(args);
  }
  return out;
}

long differingPixels(const IndexedImage& a, const IndexedImage& b) {
  long n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) n += !(a.colormap[a.pixels[i]] == b.colormap[b.pixels[i]]);
  return n;
}

// Every frame pixel shows its colour (within !MIX's percent rounding) at the
// top left of the graphics area.
void checkShowsFrame(const IndexedImage& screen, const IndexedImage& frame) {
  long wrong = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const Rgb8 want = frame.colormap[frame.at(x, y)], got = screen.colormap[screen.at(x, y)];
      wrong += std::abs(want.r - got.r) > 5 || std::abs(want.g - got.g) > 5 || std::abs(want.b - got.b) > 5;
    }
  CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("every !RVE the driver sends starts with 0 0, and draws the same under either reading") {
  const IndexedImage img = ringsImage(90, 70);
  for (const char* preset : {"strict", "compact"})
    for (int points : {32, 5})  // at 2 points a command !RVE is never the shorter spelling
      for (Tek4027Strategy s : {Tek4027Strategy::ChainedRelative, Tek4027Strategy::LayeredChained,
                                Tek4027Strategy::Shortest}) {
        Tek4027Profile profile = tek4027Preset(preset);
        profile.maxPointsPerCommand = points;
        INFO(preset << ", " << strategyName(s) << ", " << points << " points a command");
        const std::string text = driveFrame(img, profile, s);
        const auto rves = rveArguments(text);
        REQUIRE(rves.size() > 0);  // the picture's chains do go relative
        std::size_t continuations = 0;
        for (const auto& args : rves) {
          REQUIRE(args.size() >= 4);
          CHECK(args[0] == "0");
          CHECK(args[1] == "0");
          CHECK(args.size() <= static_cast<std::size_t>(2 * points));
        }
        for (std::size_t at = text.find("!RVE"); at != std::string::npos; at = text.find("!RVE", at + 1))
          continuations += text.rfind('!', at - 1) == text.rfind("!RVE", at - 1);
        if (points < 32) CHECK(continuations > 0);  // long chains split into further !RVE
        const IndexedImage moved = decodeUnder(text, reading(profile, "move"));
        const IndexedImage drawn = decodeUnder(text, reading(profile, "draw"));
        CHECK(differingPixels(moved, drawn) == 0);
        checkShowsFrame(moved, img);
        checkShowsFrame(drawn, img);
      }
}

TEST_CASE("the two readings of !RVE's first pair differ on a stream that starts it with a step") {
  // The driver's older form: the chain's next step first.
  const std::string text = "!COL C1!VEC 10 10 12 10!RVE 0 -3 -2 0\r";
  Tek4027Profile profile;
  const IndexedImage moved = decodeUnder(text, reading(profile, "move"));
  const IndexedImage drawn = decodeUnder(text, reading(profile, "draw"));
  CHECK(differingPixels(moved, drawn) == 2);  // (12, 9) and (12, 8) drawn only as a step
  // With the zero pair in front, both show the step.
  const std::string fixed = "!COL C1!VEC 10 10 12 10!RVE 0 0 0 -3 -2 0\r";
  CHECK(differingPixels(decodeUnder(fixed, reading(profile, "move")), drawn) == 0);
  CHECK(differingPixels(decodeUnder(fixed, reading(profile, "draw")), drawn) == 0);
}

TEST_CASE("tekmkfnt.c's forms: the box draws under both readings, the font stroke reads as a move") {
  Tek4027Profile profile;
  // The box: a !vec along its bottom edge, then !rve from the beam, first pair 0,0.
  const std::string box = "!col c1\r!vec 236,10,276,10\r!rve 0,0,0,400,-40,0,0,-400\r";
  const IndexedImage a = decodeUnder(box, reading(profile, "move")), b = decodeUnder(box, reading(profile, "draw"));
  CHECK(differingPixels(a, b) == 0);
  CHECK(a.at(236, a.height - 1 - 200) == 1);  // the left edge
  CHECK(a.at(276, a.height - 1 - 200) == 1);  // the right edge
  // The preview: the beam back on the origin by a zero-length !vec, then a
  // stroke whose first pair is the offset from the origin to its start.
  const std::string stroke = "!col c3\r!vec 256,110,256,110\r!rvec 20,20,0,30\r";
  const IndexedImage m = decodeUnder(stroke, reading(profile, "move")), d = decodeUnder(stroke, reading(profile, "draw"));
  auto pot = [](const IndexedImage& i, int x, int yUp) { return i.at(x, i.height - 1 - yUp); };
  CHECK(pot(m, 276, 145) == 3);  // the stroke itself, under both readings
  CHECK(pot(d, 276, 145) == 3);
  CHECK(pot(m, 266, 120) == 0);  // move: no line from the origin to the stroke
  CHECK(pot(d, 266, 120) == 3);  // draw: a line the font does not have
}
