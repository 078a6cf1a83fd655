// The 4125 profile: defaults, overrides and the errors a user sees.
#include <catch2/catch.hpp>

#include "devices/tek4125/tek4125_profile.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4125;

TEST_CASE("the default profile is a 1280x1024, 8-plane terminal at 38400 8N1") {
  Tek4125Profile p;
  CHECK(p.width == 1280);
  CHECK(p.height == 1024);
  CHECK(p.maxColors() == 256);
  CHECK(p.line().bitsPerCharacter() == 10);
  CHECK(p.line().baud == 38400);
  CHECK_NOTHROW(p.validate());
}

TEST_CASE("overrides change fields and maxColors follows planes and reserved entries") {
  Tek4125Profile p;
  applyOverrides(p, {"planes=4", "reserved=2", "baud=9600", "parity=even", "xon-xoff=off"});
  CHECK(p.planes == 4);
  CHECK(p.maxColors() == 14);
  CHECK(p.line().baud == 9600);
  CHECK(p.line().bitsPerCharacter() == 11);
  CHECK_FALSE(p.xonXoff);
  // describe() prints what applyOverride accepts, so a listing can be pasted back.
  Tek4125Profile q;
  std::string listing = describe(p);
  std::size_t start = 0;
  while (start < listing.size()) {
    const std::size_t end = listing.find('\n', start);
    applyOverride(q, listing.substr(start, end - start));
    start = end + 1;
  }
  CHECK(describe(q) == listing);
}

TEST_CASE("bad overrides are usage errors that say what is allowed") {
  Tek4125Profile p;
  auto message = [&](const std::string& kv) {
    try {
      applyOverride(p, kv);
    } catch (const Error& e) {
      CHECK(e.kind() == ErrorKind::Usage);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(message("planes=6"), Catch::Contains("planes=4 or planes=8"));
  CHECK_THAT(message("colours=3"), Catch::Contains("unknown key"));
  CHECK_THAT(message("baud=fast"), Catch::Contains("whole number"));
  CHECK_THAT(message("planes"), Catch::Contains("key=value"));
  CHECK_THAT(message("reserved=255"), Catch::Contains("reserved: '255' is out of range; give a whole number from 0 to 254"));
  CHECK_THAT(message("width=5000"), Catch::Contains("from 1 to 4096"));
  // With 16 colour map entries, the range's top is the planes', not the key's alone.
  Tek4125Profile four;
  applyOverride(four, "planes=4");
  try {
    applyOverride(four, "reserved=15");
    FAIL("reserved=15 with 4 planes was taken");
  } catch (const Error& e) {
    CHECK_THAT(e.what(), Catch::Contains("0..14"));
  }
}
