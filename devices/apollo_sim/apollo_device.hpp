#pragma once
// The Apollo entry of the device table (devices/device_table.hpp): the driver
// writes its GPR calls as a journal (gpr_journal.hpp), the emulator replays
// them on the simulated display.
#include <string>
#include <vector>

#include "devices/device.hpp"

namespace lattice::apollo {

// Settings: profile=dn660|dn660-4|dn580 (apollo_profile.hpp).
devices::Device makeDevice(const std::vector<std::string>& settings);

}  // namespace lattice::apollo
