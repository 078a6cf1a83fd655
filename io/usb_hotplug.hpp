#pragma once
// `lattice ports --wait`: block until a USB-serial adapter is present.
// With libusb (optional at build time) and a platform that supports hot-plug
// events, an arrival wakes us at once; the tty node appears a moment after
// the USB device, so sysfs is then re-read quickly until it shows up.
// Without libusb, or without hot-plug support, sysfs is polled.
#include <filesystem>
#include <string>
#include <vector>

#include "io/port_discovery.hpp"

namespace lattice::io {

struct UsbWaitOptions {
  double timeoutSeconds = 0.0;  // <= 0: wait for ever
  double pollSeconds = 0.25;    // sysfs re-read interval without hot-plug events
  bool useLibusb = true;        // false: sysfs polling only (tests with a fake tree)
  std::filesystem::path sysfsRoot = "/sys";
  std::filesystem::path devRoot = "/dev";
};

// The USB-serial ports present once at least one is (immediately if one is
// already plugged in); empty if the timeout passed first.
std::vector<SerialPortInfo> waitForUsbSerialPorts(const UsbWaitOptions& options);

// How waitForUsbSerialPorts would learn of an arrival here: "libusb hot-plug
// events" or "polling sysfs" (with the reason libusb is not used).
std::string usbWaitMechanism(bool useLibusb = true);

}  // namespace lattice::io
