#pragma once
// The tek4125 entry of the device table (devices/device_table.hpp).
#include <string>
#include <vector>

#include "devices/device.hpp"

namespace lattice::tek4125 {

// A tek4125 configured by its profile's key=value settings (--set).
devices::Device makeDevice(const std::vector<std::string>& settings);

}  // namespace lattice::tek4125
