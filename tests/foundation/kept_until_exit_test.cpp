// foundation/system/kept_until_exit.hpp: what is kept until the process
// exits is not destroyed when its owner lets go of it.
#include <catch2/catch.hpp>

#include <memory>

#include "foundation/system/kept_until_exit.hpp"

using namespace lattice;

namespace {

struct CountsDestruction {
  int* destroyed;
  ~CountsDestruction() { ++*destroyed; }
};

}  // namespace

TEST_CASE("kept until exit: the object outlives its owner, and is listed") {
  static int destroyed = 0;  // static: read after the test too, if ever destroyed at exit
  const std::size_t before = keptUntilExit().size();
  std::unique_ptr<CountsDestruction> owned(new CountsDestruction{&destroyed});
  const CountsDestruction* address = owned.get();
  keepUntilExit(std::move(owned));
  CHECK(owned == nullptr);
  CHECK(destroyed == 0);
  REQUIRE(keptUntilExit().size() == before + 1);
  CHECK(keptUntilExit().back().get() == address);
}
