// The device table: every device by name, each made from its profile with a
// screen, a driver, an emulator and its memory figures.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "devices/device_table.hpp"
#include "foundation/error.hpp"

using namespace lattice;

TEST_CASE("the device table names every device and makes each with its screen") {
  const std::vector<std::string> names = devices::deviceNames();
  CHECK(names == std::vector<std::string>{"tek4125", "tek4027", "tek4014", "apollo", "sixel"});
  for (const std::string& name : names) {
    const devices::Device d = devices::makeDevice(name);
    INFO(name);
    CHECK(d.name == name);
    CHECK(d.width > 0);
    CHECK(d.height > 0);
    CHECK(d.makeDriver);
    CHECK(d.makeEmulator);
    CHECK(d.emulatorMemory >= static_cast<std::uint64_t>(d.width) * static_cast<std::uint64_t>(d.height));
  }
  CHECK(devices::makeDevice("apollo", {"profile=dn580"}).width == 1280);
  CHECK_THROWS_AS(devices::makeDevice("vt100"), Error);
  CHECK_THROWS_AS(devices::makeDevice("apollo", {"planes=3"}), Error);
}
