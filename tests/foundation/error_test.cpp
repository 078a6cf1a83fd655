#include <catch2/catch.hpp>

#include "foundation/error.hpp"
#include "foundation/progress.hpp"

using namespace lattice;

TEST_CASE("locate formats path:line:col like a compiler") {
  CHECK(locate("a.toml", 3, 7, "bad") == "a.toml:3:7: bad");
  CHECK(locate("a.toml", 3, 0, "bad") == "a.toml:3: bad");
  CHECK(locate("a.toml", 0, 0, "bad") == "a.toml: bad");
}

TEST_CASE("error kinds are the documented exit codes") {
  Error e(ErrorKind::Stalled, "held by XOFF");
  CHECK(e.exitCode() == 6);
  CHECK(std::string(e.what()) == "held by XOFF");
  CHECK(Error(ErrorKind::Usage, "").exitCode() == 2);
  CHECK(Error(ErrorKind::Input, "").exitCode() == 3);
  CHECK(Error(ErrorKind::HangUp, "").exitCode() == 7);
}

TEST_CASE("progress is silent when stderr is not a terminal and counts anyway") {
  Progress p("test", 10, "rows");
  // ctest pipes stderr, so the bar must not draw there.
  CHECK_FALSE(p.enabled());
  p.advance(3);
  p.advance();
  p.finish();
  p.finish();  // idempotent
  SUCCEED("finish twice is harmless");
}
