#pragma once
// The device table: every device Lattice drives, one explicit entry each
// (Tungsten's factory tables: no registration side effects). The CLI's
// --device choices and help, the memory planner and the tests all read it,
// so adding a device is a folder under devices/ plus one line here.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devices/device.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::devices {

struct DeviceEntry {
  std::string_view name;        // --device NAME
  std::string_view summary;     // one line for --help
  // Settings are the profile's key=value overrides (--set); a bad one throws
  // Error(Usage) listing the profile's keys.
  Device (*make)(const std::vector<std::string>& settings);
  // The keys `make` takes, from the profile's settings table
  // (foundation/settings_schema.hpp): what docs/cli.md lists for the device.
  std::vector<SettingInfo> (*settings)();
};

std::span<const DeviceEntry> deviceTable();
std::vector<std::string> deviceNames();
// Error(Usage) naming the devices there are when `name` is none of them.
const DeviceEntry& deviceEntry(std::string_view name);
Device makeDevice(std::string_view name, const std::vector<std::string>& settings = {});

}  // namespace lattice::devices
