#include "io/port_discovery.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <system_error>

#include "foundation/error.hpp"

namespace lattice::io {
namespace fs = std::filesystem;
namespace {

// One line of a sysfs attribute, trailing whitespace dropped; "" if absent.
std::string readAttribute(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  if (!in || !std::getline(in, line)) return {};
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

std::string driverName(const fs::path& deviceDir) {
  std::error_code ec;
  fs::path target = fs::read_symlink(deviceDir / "driver", ec);
  return ec ? std::string() : target.filename().string();
}

// The USB device above a tty: the nearest ancestor with idVendor/idProduct.
// Bounded by the sysfs root so a malformed tree cannot walk us out of it.
bool findUsbDevice(const fs::path& deviceDir, const fs::path& sysfsRoot, SerialPortInfo& info) {
  fs::path dir = deviceDir;
  for (int depth = 0; depth < 8 && !dir.empty(); ++depth) {
    std::error_code ec;
    if (fs::exists(dir / "idVendor", ec) && fs::exists(dir / "idProduct", ec)) {
      info.vendorId = readAttribute(dir / "idVendor");
      info.productId = readAttribute(dir / "idProduct");
      info.manufacturer = readAttribute(dir / "manufacturer");
      info.product = readAttribute(dir / "product");
      info.serial = readAttribute(dir / "serial");
      return true;
    }
    if (dir == sysfsRoot || dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return false;
}

std::string describeKind(SerialPortInfo::Kind kind) {
  switch (kind) {
    case SerialPortInfo::Kind::UsbSerial:
      return "USB-serial";
    case SerialPortInfo::Kind::Uart:
      return "UART";
    case SerialPortInfo::Kind::Other:
      break;
  }
  return "serial";
}

}  // namespace

std::string SerialPortInfo::describe() const {
  if (kind != Kind::UsbSerial) return fmt::format("{} ({}, driver {})", devicePath, describeKind(kind), driver);
  std::string label = manufacturer.empty() ? product : product.empty() ? manufacturer : manufacturer + " " + product;
  if (label.empty()) label = "USB-serial adapter";
  std::string text = fmt::format("{} ({}, {}:{}", devicePath, label, vendorId, productId);
  if (!serial.empty()) text += ", serial " + serial;
  return text + ", driver " + driver + ")";
}

std::vector<SerialPortInfo> listSerialPorts(const fs::path& sysfsRoot, const fs::path& devRoot) {
  std::vector<SerialPortInfo> ports;
  std::error_code ec;
  fs::path classDir = sysfsRoot / "class" / "tty";
  fs::directory_iterator it(classDir, ec);
  if (ec) return ports;
  fs::path canonicalRoot = fs::weakly_canonical(sysfsRoot, ec);
  for (const auto& entry : it) {
    fs::path ttyDir = entry.path();
    // No device link: a virtual console, pty or the like, not a line.
    std::error_code linkEc;
    fs::path deviceDir = fs::canonical(ttyDir / "device", linkEc);
    if (linkEc) continue;
    SerialPortInfo info;
    info.name = ttyDir.filename().string();
    info.devicePath = (devRoot / info.name).string();
    info.driver = driverName(deviceDir);
    if (findUsbDevice(deviceDir, canonicalRoot, info)) {
      info.kind = SerialPortInfo::Kind::UsbSerial;
    } else {
      // Built-in 8250 UARTs register ttyS0..ttyS31 whether or not the chip
      // exists; type 0 (PORT_UNKNOWN) means there is none behind the name.
      std::string type = readAttribute(ttyDir / "type");
      if (!type.empty() && type == "0") continue;
      info.kind = info.driver.find("serial") != std::string::npos || !type.empty() ? SerialPortInfo::Kind::Uart
                                                                                   : SerialPortInfo::Kind::Other;
    }
    ports.push_back(std::move(info));
  }
  std::sort(ports.begin(), ports.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return ports;
}

std::vector<SerialPortInfo> usbSerialPorts(const std::vector<SerialPortInfo>& ports) {
  std::vector<SerialPortInfo> usb;
  std::copy_if(ports.begin(), ports.end(), std::back_inserter(usb),
               [](const auto& p) { return p.kind == SerialPortInfo::Kind::UsbSerial; });
  return usb;
}

std::string chooseAutoPort(const std::vector<SerialPortInfo>& ports) {
  auto usb = usbSerialPorts(ports);
  if (usb.size() == 1) return usb.front().devicePath;
  if (usb.empty()) {
    std::string others;
    for (const auto& p : ports) others += "\n  " + p.describe();
    throw Error(ErrorKind::Serial,
                fmt::format("--port auto: no USB-serial adapter found; plug one in (`lattice ports --wait` waits "
                            "for it) or name a port with --port{}",
                            others.empty() ? std::string(" (no serial ports found at all)")
                                           : "; other ports present:" + others));
  }
  std::string list;
  for (const auto& p : usb) list += "\n  " + p.describe();
  throw Error(ErrorKind::Serial,
              fmt::format("--port auto: {} USB-serial adapters found, so which one is the terminal is not clear; "
                          "name it with --port:{}",
                          usb.size(), list));
}

}  // namespace lattice::io
