// The strict form set (tek4125_forms.hpp) checked on the bytes themselves,
// not through our own emulator: what the stream contains and what it never
// contains. Then through the emulator under every reading no source
// settles (the readings rr-origin, rh-origin, surface-planes, pixel-bits,
// raster-rows, power-up-map: readings_keys.hpp): a strict stream must draw the same picture
// under each, while a compact one shows that it depends on them.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "tests/devices/tek4125/readings_keys.hpp"
#include "tests/devices/tek4125/tek_test_support.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

// The stream with each ESC ? turned back into the DEL it stands for.
std::vector<std::uint8_t> unescaped(const std::vector<std::uint8_t>& b) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b[i] == 0x1B && i + 1 < b.size() && b[i + 1] == '?') {
      out.push_back(0x7F);
      ++i;
    } else {
      out.push_back(b[i]);
    }
  }
  return out;
}

struct Command {
  std::string name;
  std::size_t at;  // offset of the first parameter byte
};

std::vector<Command> commands(const std::vector<std::uint8_t>& b) {
  std::vector<Command> out;
  for (std::size_t i = 0; i + 2 < b.size(); ++i)
    if (b[i] == 0x1B && b[i + 1] >= 'A' && b[i + 1] <= 'Z' && b[i + 2] >= 'A' && b[i + 2] <= 'Z')
      out.push_back(Command{std::string{char(b[i + 1]), char(b[i + 2])}, i + 3});
  return out;
}

bool fullXyAt(const std::vector<std::uint8_t>& b, std::size_t at) {
  auto in = [&](std::size_t i, int lo, int hi) { return at + i < b.size() && b[at + i] >= lo && b[at + i] <= hi; };
  return in(0, 0x20, 0x3F) && in(1, 0x60, 0x7F) && in(2, 0x60, 0x7F) && in(3, 0x20, 0x3F) && in(4, 0x40, 0x5F);
}

std::size_t firstOf(const std::vector<Command>& cs, std::initializer_list<const char*> names) {
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (const char* n : names)
      if (cs[i].name == n) return i;
  return cs.size();
}

Tek4125Profile strictProfile(int planes = 8) {
  Tek4125Profile p;
  p.planes = planes;
  return p;
}

}  // namespace

TEST_CASE("a strict stream: set-up first, full xy, one colour per TG, no raw DEL, RP only at 4 bits") {
  for (int colors : {12, 200}) {
    INFO(colors << " colours");
    const Tek4125Profile profile = strictProfile();
    CHECK(profile.forms == "strict");  // the default
    const IndexedImage img = scene(301, 97, colors);
    const std::vector<std::uint8_t> raw = encode(img, profile);
    for (std::uint8_t c : raw) REQUIRE(c != 0x7F);  // RAL-CGM's way: ESC ? instead
    const std::vector<std::uint8_t> b = unescaped(raw);
    const std::vector<Command> cs = commands(b);
    REQUIRE(b.size() > 4);
    CHECK(std::vector<std::uint8_t>(b.begin(), b.begin() + 4) == std::vector<std::uint8_t>{0x1B, '%', '!', '0'});
    const std::size_t drawing = firstOf(cs, {"RP", "RL", "RR", "RH"});
    for (const char* setUp : {"KI", "RD", "TM", "TB", "TG", "RU", "RS"}) {
      INFO(setUp);
      CHECK(firstOf(cs, {setUp}) < drawing);
    }
    const Command rd = cs[firstOf(cs, {"RD"})];
    CHECK(b[rd.at] == '1');  // one surface ...
    CHECK(b[rd.at + 1] == (colors > 16 ? '8' : '4'));  // ... of as many planes as RU writes bits
    int tgCommands = 0;
    for (const Command& c : cs) {
      if (c.name == "TG") {
        ++tgCommands;
        CHECK(b[c.at] == '1');  // surface 1
        CHECK(b[c.at + 1] == '4');  // one entry: four integers
      }
      if (c.name == "RH" || c.name == "RR" || c.name == "RS") {
        INFO(c.name << " at " << c.at);
        CHECK(fullXyAt(b, c.at));
        CHECK(fullXyAt(b, c.at + 5 * (c.name != "RH")));
      }
      if (colors > 16) CHECK(c.name != "RP");
    }
    CHECK(tgCommands == colors);
    const Command rs = cs[firstOf(cs, {"RS"})];  // the whole screen: (0, 0) to (1279, 1023)
    CHECK(std::vector<std::uint8_t>(b.begin() + static_cast<long>(rs.at), b.begin() + static_cast<long>(rs.at) + 10) ==
          std::vector<std::uint8_t>{0x20, 0x60, 0x60, 0x20, 0x40, 0x27, 0x6F, 0x7F, 0x29, 0x5F});
    const Command ru = cs[firstOf(cs, {"RU"})];
    CHECK(b[ru.at + 2] == (colors > 16 ? '8' : '4'));
    CHECK(b[ru.at + 2] == b[rd.at + 1]);  // as the sources pair them: bits a pixel = the surface's planes
  }
}

TEST_CASE("a strict stream draws the same picture under every unsettled reading, a compact one does not") {
  struct Reading {
    std::vector<std::string> keys;
    bool compactDiffersAt12, compactDiffersAt200;  // where a compact stream is known to depend on it
  };
  const std::vector<Reading> readings = {
      {{"rr-origin=viewport"}, false, true},
      {{"rh-origin=screen"}, false, true},
      {{"surface-planes=4"}, false, true},
      {{"pixel-bits=surface"}, true, false},  // compact sends RU 4 bits on 8 planes without RD
      {{"raster-rows=down"}, false, false},   // neither form set lets a span wrap
      {{"power-up-map=ral-cgm"}, false, false},
      {{"rr-origin=viewport", "rh-origin=screen", "surface-planes=1", "pixel-bits=surface", "raster-rows=down"},
       true, true}};
  auto screenUnder = [&](const std::vector<std::uint8_t>& bytes, const Tek4125Profile& p,
                         const std::vector<std::string>& reading) {
    Tek4125Decoder d(p, readingsOf(reading));
    d.feed(bytes);
    d.finish();
    return d.image();
  };
  for (int colors : {12, 200}) {
    const IndexedImage img = scene(160, 120, colors);
    for (const std::string forms : {"strict", "compact"}) {
      Tek4125Profile profile;
      profile.forms = forms;
      // Compact with the older strategy, which uses RR for long runs.
      const Tek4125DriverOptions options =
          forms == "strict" ? Tek4125DriverOptions{} : tek4125Strategy("spans").options;
      const auto bytes = encode(img, profile, options);
      const IndexedImage usual = screenUnder(bytes, profile, {});
      if (forms == "strict") REQUIRE(cutPicture(usual, profile, img.width, img.height).pixels == img.pixels);
      for (const Reading& reading : readings) {
        INFO(forms << ", " << colors << " colours, under " << reading.keys.back());
        const IndexedImage other = screenUnder(bytes, profile, reading.keys);
        long differing = 0;
        for (std::size_t i = 0; i < usual.pixels.size(); ++i)
          differing += !(usual.colormap[usual.pixels[i]] == other.colormap[other.pixels[i]]);
        if (forms == "strict") CHECK(differing == 0);
        else if (colors > 16 ? reading.compactDiffersAt200 : reading.compactDiffersAt12) CHECK(differing > 0);
      }
    }
  }
}

TEST_CASE("a DEL inside a parameter goes as ESC ? in strict, raw in compact, and both decode alike") {
  // A y with (y >> 2) & 31 == 31 has Lo-Y = DEL: screen rows 508..511 for
  // strict's screen-wide viewport, picture rows 124..127 for compact's.
  const IndexedImage img = noise(1280, 140, 200, 4u);  // screen rows 442..581
  Tek4125Profile strict, compact;
  compact.forms = "compact";
  const auto s = encode(img, strict), c = encode(img, compact);
  long rawStrict = 0, escapes = 0, rawCompact = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    rawStrict += s[i] == 0x7F;
    escapes += s[i] == 0x1B && i + 1 < s.size() && s[i + 1] == '?';
  }
  for (std::uint8_t b : c) rawCompact += b == 0x7F;
  CHECK(rawStrict == 0);
  CHECK(escapes > 0);
  CHECK(rawCompact > 0);
  Tek4125Decoder a(strict), b(compact);
  a.feed(s);
  b.feed(c);
  CHECK(a.report().malformed == 0);
  CHECK(cutPicture(a.image(), strict, img.width, img.height).pixels == img.pixels);
  CHECK(cutPicture(b.image(), compact, img.width, img.height).pixels == img.pixels);
}

namespace {

// Length of an xy in OpenVnmrJ's form (tek_coord0): [Hi-Y] Extra Lo-Y
// [Hi-X] Lo-X, Extra and Lo-Y always there; 0 when the bytes are not one.
std::size_t highShortXyAt(const std::vector<std::uint8_t>& b, std::size_t at) {
  auto in = [&](std::size_t i, int lo, int hi) { return i < b.size() && b[i] >= lo && b[i] <= hi; };
  std::size_t i = at;
  if (in(i, 0x20, 0x3F)) ++i;  // Hi-Y
  if (!in(i, 0x60, 0x7F) || !in(i + 1, 0x60, 0x7F)) return 0;  // Extra, Lo-Y
  i += 2;
  if (in(i, 0x20, 0x3F)) ++i;  // Hi-X
  return in(i, 0x40, 0x5F) ? i + 1 - at : 0;
}

}  // namespace

TEST_CASE("xy-short=on: strict's RR and RH xys leave out an unchanged Hi-Y and Hi-X, the screen is the same") {
  CHECK_FALSE(Tek4125Profile{}.xyShort);  // off by default: strict's default bytes stay
  for (int colors : {12, 200}) {
    INFO(colors << " colours");
    const IndexedImage img = scene(301, 97, colors);
    const Tek4125Profile off = strictProfile();
    Tek4125Profile on = off;
    applyOverride(on, "xy-short=on");
    REQUIRE(on.xyShort);
    const auto offBytes = encode(img, off), onBytes = encode(img, on);
    INFO(offBytes.size() << " bytes, " << onBytes.size() << " with xy-short=on");
    CHECK(onBytes.size() < offBytes.size());
    const std::vector<std::uint8_t> b = unescaped(onBytes);
    const std::vector<Command> cs = commands(b);
    int shortened = 0;
    bool afterPixelXy = false;  // the last xy belonged to an RR or RH
    for (const Command& c : cs) {
      if (c.name == "RS") {
        CHECK(fullXyAt(b, c.at));
        CHECK(fullXyAt(b, c.at + 5));
        afterPixelXy = false;
      }
      if (c.name != "RH" && c.name != "RR") continue;
      INFO(c.name << " at " << c.at);
      std::size_t at = c.at;
      for (int corner = 0; corner < (c.name == "RR" ? 2 : 1); ++corner) {
        const std::size_t n = highShortXyAt(b, at);
        REQUIRE(n >= 3);
        if (!afterPixelXy) CHECK(n == 5);  // the first after RS is sent whole
        shortened += n < 5;
        afterPixelXy = true;
        at += n;
      }
    }
    CHECK(shortened > 0);
    for (const std::vector<std::uint8_t>* bytes : {&offBytes, &onBytes}) {
      Tek4125Decoder d(off);
      d.feed(*bytes);
      d.finish();
      CHECK(d.report().malformed == 0);
      CHECK(cutPicture(d.image(), off, img.width, img.height).pixels == img.pixels);
    }
  }
  Tek4125Profile compact;
  compact.forms = "compact";
  Tek4125Profile compactOn = compact;
  applyOverride(compactOn, "xy-short=on");  // compact's own short forms go further: no change
  const IndexedImage img = scene(160, 120, 200);
  CHECK(encode(img, compact) == encode(img, compactOn));
}

TEST_CASE("ru-bits=fit: compact writes as few bits a pixel as the palette needs, strict ignores it") {
  for (int colors : {20, 40, 100}) {
    INFO(colors << " colours");
    const IndexedImage img = scene(301, 97, colors);
    Tek4125Profile compact;
    compact.forms = "compact";
    Tek4125Profile fit = compact;
    applyOverride(fit, "ru-bits=fit");
    const int bits = colors <= 32 ? 5 : colors <= 64 ? 6 : 7;
    CHECK(fit.pixelBitsFor(colors) == bits);
    CHECK(compact.pixelBitsFor(colors) == 8);
    const auto planes = encode(img, compact), fitted = encode(img, fit);
    INFO(planes.size() << " bytes at 8 bits, " << fitted.size() << " at " << bits);
    CHECK(fitted.size() < planes.size());
    const std::vector<Command> cs = commands(fitted);
    const Command ru = cs[firstOf(cs, {"RU"})];
    CHECK(fitted[ru.at + 2] == '0' + bits);  // RU 1 11 <bits>
    Tek4125Decoder d(compact);  // the reading of RU's bits is the default (pixel-bits=ru)
    d.feed(fitted);
    d.finish();
    CHECK(d.report().malformed == 0);
    CHECK(cutPicture(d.image(), compact, img.width, img.height).pixels == img.pixels);
    Tek4125Profile strictFit = strictProfile();
    applyOverride(strictFit, "ru-bits=fit");  // no source writes such depths: strict stays at its planes
    CHECK(encode(img, strictFit) == encode(img, strictProfile()));
  }
  CHECK(Tek4125Profile{}.pixelBitsFor(16) == 4);
}
