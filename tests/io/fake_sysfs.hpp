#pragma once
// A miniature /sys (and /dev) in a temporary directory, shaped like the real
// one: /sys/class/tty/<name>/device is a symlink into /sys/devices, a USB
// adapter's tty sits below its interface below the USB device that carries
// idVendor, idProduct, manufacturer, product and serial.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

namespace lattice::testing {

class FakeSysfs {
 public:
  FakeSysfs() {
    static std::atomic<int> counter{0};
    root_ = std::filesystem::temp_directory_path() /
            ("lattice-sysfs-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(sys() / "class" / "tty");
    std::filesystem::create_directories(dev());
  }
  ~FakeSysfs() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  FakeSysfs(const FakeSysfs&) = delete;
  FakeSysfs& operator=(const FakeSysfs&) = delete;

  std::filesystem::path sys() const { return root_ / "sys"; }
  std::filesystem::path dev() const { return root_ / "dev"; }

  // e.g. addUsbAdapter("ttyUSB0", "1-1", "ftdi_sio", "0403", "6001", "FTDI", "FT232R USB UART", "A50285BI")
  void addUsbAdapter(const std::string& tty, const std::string& usbPort, const std::string& driver,
                     const std::string& vendor, const std::string& product, const std::string& manufacturerName,
                     const std::string& productName, const std::string& serial) {
    auto usbDevice = sys() / "devices" / "pci0000:00" / "0000:00:14.0" / "usb1" / usbPort;
    auto interface = usbDevice / (usbPort + ":1.0");
    auto ttyDevice = interface / tty;  // usb-serial drivers add a level; cdc_acm binds the interface itself
    std::filesystem::create_directories(ttyDevice);
    write(usbDevice / "idVendor", vendor);
    write(usbDevice / "idProduct", product);
    if (!manufacturerName.empty()) write(usbDevice / "manufacturer", manufacturerName);
    if (!productName.empty()) write(usbDevice / "product", productName);
    if (!serial.empty()) write(usbDevice / "serial", serial);
    linkDriver(ttyDevice, driver);
    addClassEntry(tty, ttyDevice, "");
  }

  // A built-in UART (8250); type "0" is an 8250 name with no chip behind it.
  void addUart(const std::string& tty, const std::string& type) {
    auto device = sys() / "devices" / "pnp0" / ("00:0" + tty.substr(tty.size() - 1));
    std::filesystem::create_directories(device);
    linkDriver(device, "serial");
    addClassEntry(tty, device, type);
  }

  // A virtual console or pty: in /sys/class/tty, but no device link.
  void addVirtual(const std::string& tty) {
    std::filesystem::create_directories(sys() / "devices" / "virtual" / "tty" / tty);
    std::filesystem::create_directory_symlink(sys() / "devices" / "virtual" / "tty" / tty,
                                              sys() / "class" / "tty" / tty);
  }

 private:
  static void write(const std::filesystem::path& file, const std::string& value) { std::ofstream(file) << value << "\n"; }

  void linkDriver(const std::filesystem::path& device, const std::string& driver) {
    auto driverDir = sys() / "bus" / "drivers" / driver;
    std::filesystem::create_directories(driverDir);
    std::filesystem::create_directory_symlink(driverDir, device / "driver");
  }

  void addClassEntry(const std::string& tty, const std::filesystem::path& device, const std::string& type) {
    auto entry = sys() / "class" / "tty" / tty;
    std::filesystem::create_directories(entry);
    // Relative, like the kernel's "../../../1-1:1.0/ttyUSB0" links.
    std::filesystem::create_directory_symlink(std::filesystem::relative(device, entry), entry / "device");
    if (!type.empty()) write(entry / "type", type);
  }

  std::filesystem::path root_;
};

}  // namespace lattice::testing
