// `lattice ports --wait` on a fake sysfs tree (sysfs polling; libusb events
// cannot be faked and are not needed to find the tty).
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "fake_sysfs.hpp"
#include "io/usb_hotplug.hpp"

using namespace lattice;
using namespace lattice::io;
using lattice::testing::FakeSysfs;

namespace {

UsbWaitOptions fakeWait(const FakeSysfs& fake, double timeout) {
  UsbWaitOptions options;
  options.timeoutSeconds = timeout;
  options.pollSeconds = 0.02;
  options.useLibusb = false;
  options.sysfsRoot = fake.sys();
  options.devRoot = fake.dev();
  return options;
}

}  // namespace

TEST_CASE("Waiting returns the adapter once it is plugged in", "[ports]") {
  FakeSysfs fake;
  fake.addUart("ttyS0", "4");
  std::thread plug([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    fake.addUsbAdapter("ttyUSB0", "1-1", "ftdi_sio", "0403", "6001", "FTDI", "FT232R", "X1");
  });
  auto ports = waitForUsbSerialPorts(fakeWait(fake, 5.0));
  plug.join();
  REQUIRE(ports.size() == 1);
  CHECK(ports[0].name == "ttyUSB0");
  CHECK(ports[0].serial == "X1");
}

TEST_CASE("Waiting returns at once when an adapter is already present", "[ports]") {
  FakeSysfs fake;
  fake.addUsbAdapter("ttyACM0", "2-1", "cdc_acm", "2341", "0043", "Arduino", "Uno", "");
  auto ports = waitForUsbSerialPorts(fakeWait(fake, 0.01));
  REQUIRE(ports.size() == 1);
  CHECK(ports[0].name == "ttyACM0");
}

TEST_CASE("Waiting gives up after the timeout when nothing is plugged in", "[ports]") {
  FakeSysfs fake;
  fake.addUart("ttyS0", "4");
  CHECK(waitForUsbSerialPorts(fakeWait(fake, 0.1)).empty());
}

TEST_CASE("The wait mechanism is named", "[ports]") {
  CHECK(usbWaitMechanism(false) == "polling sysfs");
  auto mechanism = usbWaitMechanism(true);
  CHECK((mechanism == "libusb hot-plug events" || mechanism.rfind("polling sysfs (", 0) == 0));
}
