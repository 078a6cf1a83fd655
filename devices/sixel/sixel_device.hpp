#pragma once
// The sixel entry of the device table (devices/device_table.hpp).
#include <string>
#include <vector>

#include "devices/device.hpp"

namespace lattice::sixel {

// A sixel terminal configured by its profile's key=value settings (--set).
devices::Device makeDevice(const std::vector<std::string>& settings);

}  // namespace lattice::sixel
