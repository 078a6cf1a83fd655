#pragma once
// The tek4014 entry of the device table (devices/device_table.cpp).
#include <string>
#include <vector>

#include "devices/device.hpp"

namespace lattice::tek4014 {

devices::Device makeDevice(const std::vector<std::string>& settings);

}  // namespace lattice::tek4014
