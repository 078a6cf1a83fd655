#pragma once
// Which serial ports this machine has, read from sysfs: every
// /sys/class/tty/<name> with a `device` link is backed by hardware (virtual
// consoles and ptys have none). A USB adapter's tty hangs below its USB
// interface; walking up from there to the first directory with idVendor and
// idProduct finds the USB device and its manufacturer, product and serial
// strings. The roots are parameters so tests read a fake tree.
#include <filesystem>
#include <string>
#include <vector>

namespace lattice::io {

struct SerialPortInfo {
  enum class Kind { UsbSerial, Uart, Other };
  std::string name;        // ttyUSB0
  std::string devicePath;  // /dev/ttyUSB0
  std::string driver;      // ftdi_sio, cp210x, cdc_acm, serial8250...
  Kind kind = Kind::Other;
  // USB adapters only; strings empty when the device does not provide them.
  std::string vendorId;  // 4 hex digits, e.g. 0403
  std::string productId;
  std::string manufacturer;
  std::string product;
  std::string serial;

  // "ttyUSB0 (FTDI FT232R USB UART, 0403:6001, serial A50285BI)"
  std::string describe() const;
};

// Ports sorted by name. A missing or unreadable tree gives an empty list.
std::vector<SerialPortInfo> listSerialPorts(const std::filesystem::path& sysfsRoot = "/sys",
                                            const std::filesystem::path& devRoot = "/dev");

std::vector<SerialPortInfo> usbSerialPorts(const std::vector<SerialPortInfo>& ports);

// `--port auto`: the device path of the only USB-serial adapter. With none
// or several, Error(Serial) says so and lists what there is.
std::string chooseAutoPort(const std::vector<SerialPortInfo>& ports);

}  // namespace lattice::io
