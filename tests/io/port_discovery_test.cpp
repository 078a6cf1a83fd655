// Port listing and `--port auto` read a fake sysfs tree.
#include <catch2/catch.hpp>

#include "fake_sysfs.hpp"
#include "io/port_discovery.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;
using lattice::testing::FakeSysfs;

namespace {

std::string autoError(const FakeSysfs& fake) {
  try {
    chooseAutoPort(listSerialPorts(fake.sys(), fake.dev()));
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Serial);
    return e.what();
  }
  FAIL("--port auto should have refused");
  return {};
}

}  // namespace

TEST_CASE("Ports are listed from sysfs: USB adapter details, UARTs, no virtual ttys", "[ports]") {
  FakeSysfs fake;
  fake.addUsbAdapter("ttyUSB0", "1-2", "ftdi_sio", "0403", "6001", "FTDI", "FT232R USB UART", "A50285BI");
  fake.addUart("ttyS0", "4");
  fake.addUart("ttyS1", "0");  // a name the 8250 driver registers with no chip behind it
  fake.addVirtual("tty3");
  fake.addVirtual("ptmx");

  auto ports = listSerialPorts(fake.sys(), fake.dev());
  REQUIRE(ports.size() == 2);
  const auto& usb = ports[1];
  CHECK(ports[0].name == "ttyS0");
  CHECK(ports[0].kind == SerialPortInfo::Kind::Uart);
  CHECK(ports[0].driver == "serial");
  CHECK(usb.name == "ttyUSB0");
  CHECK(usb.devicePath == (fake.dev() / "ttyUSB0").string());
  CHECK(usb.kind == SerialPortInfo::Kind::UsbSerial);
  CHECK(usb.driver == "ftdi_sio");
  CHECK(usb.vendorId == "0403");
  CHECK(usb.productId == "6001");
  CHECK(usb.manufacturer == "FTDI");
  CHECK(usb.product == "FT232R USB UART");
  CHECK(usb.serial == "A50285BI");
  CHECK(usb.describe().find("FTDI FT232R USB UART, 0403:6001, serial A50285BI") != std::string::npos);
}

TEST_CASE("An adapter without string descriptors is still listed", "[ports]") {
  FakeSysfs fake;
  fake.addUsbAdapter("ttyACM0", "3-1", "cdc_acm", "2341", "0043", "", "", "");
  auto ports = listSerialPorts(fake.sys(), fake.dev());
  REQUIRE(ports.size() == 1);
  CHECK(ports[0].kind == SerialPortInfo::Kind::UsbSerial);
  CHECK(ports[0].vendorId == "2341");
  CHECK(ports[0].manufacturer.empty());
  CHECK(ports[0].describe().find("USB-serial adapter, 2341:0043") != std::string::npos);
}

TEST_CASE("A missing sysfs tree lists nothing rather than failing", "[ports]") {
  CHECK(listSerialPorts("/nonexistent/lattice-sysfs", "/dev").empty());
}

TEST_CASE("Port auto-selection (--port auto) with zero, one or two USB adapters", "[ports]") {
  FakeSysfs fake;
  fake.addUart("ttyS0", "4");
  auto none = autoError(fake);
  CHECK(none.find("no USB-serial adapter") != std::string::npos);
  CHECK(none.find("ttyS0") != std::string::npos);  // says what there is instead

  fake.addUsbAdapter("ttyUSB0", "1-1", "cp210x", "10c4", "ea60", "Silicon Labs", "CP2102", "0001");
  CHECK(chooseAutoPort(listSerialPorts(fake.sys(), fake.dev())) == (fake.dev() / "ttyUSB0").string());

  fake.addUsbAdapter("ttyUSB1", "1-4", "ch341", "1a86", "7523", "", "USB Serial", "");
  auto two = autoError(fake);
  CHECK(two.find("2 USB-serial adapters") != std::string::npos);
  CHECK(two.find("ttyUSB0") != std::string::npos);
  CHECK(two.find("ttyUSB1") != std::string::npos);
  CHECK(two.find("--port") != std::string::npos);
}
