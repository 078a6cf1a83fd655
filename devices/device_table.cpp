#include "devices/device_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "devices/apollo_sim/apollo_device.hpp"
#include "devices/apollo_sim/apollo_profile.hpp"
#include "devices/sixel/sixel_device.hpp"
#include "devices/sixel/sixel_profile.hpp"
#include "devices/tek4014/tek4014_device.hpp"
#include "devices/tek4014/tek4014_profile.hpp"
#include "devices/tek4027/tek4027_device.hpp"
#include "devices/tek4027/tek4027_profile.hpp"
#include "devices/tek4125/tek4125_device.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "foundation/error.hpp"

namespace lattice::devices {
namespace {

const DeviceEntry kDevices[] = {
    {"tek4125", "Tektronix 4125: a 4100-series command stream", &tek4125::makeDevice,
     [] { return settingInfos(tek4125::tek4125Settings()); }},
    {"tek4027", "Tektronix 4027: a !-command stream, eight paint pots", &tek4027::makeDevice,
     [] { return settingInfos(tek4027::tek4027Settings()); }},
    {"tek4014", "Tektronix 4014 (and xterm -t): dithered dots, 10- or 12-bit addresses (--set bits=12)",
     &tek4014::makeDevice, [] { return settingInfos(tek4014::tek4014Settings()); }},
    {"apollo", "simulated Apollo DN660/DN580: its GPR calls as a journal (--set profile=dn660|dn660-4|dn580)",
     &apollo::makeDevice, [] { return settingInfos(apollo::apolloSettings()); }},
    {"sixel", "DEC sixel graphics for a VT340, xterm -ti vt340, mlterm, foot, WezTerm (--set registers=256)",
     &sixel::makeDevice, [] { return settingInfos(sixel::sixelSettings()); }},
};

}  // namespace

std::span<const DeviceEntry> deviceTable() { return kDevices; }

std::vector<std::string> deviceNames() {
  std::vector<std::string> names;
  for (const DeviceEntry& e : kDevices) names.emplace_back(e.name);
  return names;
}

const DeviceEntry& deviceEntry(std::string_view name) {
  for (const DeviceEntry& e : kDevices)
    if (e.name == name) return e;
  throw Error(ErrorKind::Usage, fmt::format("unknown device '{}'; choose {}", name, fmt::join(deviceNames(), ", ")));
}

Device makeDevice(std::string_view name, const std::vector<std::string>& settings) {
  return deviceEntry(name).make(settings);
}

}  // namespace lattice::devices
