#pragma once
// The tek4027 entry of the device table (devices/device_table.hpp).
#include <string>
#include <vector>

#include "devices/device.hpp"

namespace lattice::tek4027 {

// A tek4027 configured by its profile's key=value settings (--set).
devices::Device makeDevice(const std::vector<std::string>& settings);

}  // namespace lattice::tek4027
