// `lattice ports`: the serial ports of this machine, USB adapters with their
// vendor/product/serial, and `--wait` for an adapter to be plugged in.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>
#include <string>

#include "app/commands/commands.hpp"
#include "app/cli/number_flags.hpp"
#include "io/port_discovery.hpp"
#include "io/usb_hotplug.hpp"
#include "foundation/error.hpp"

namespace {

struct PortsArgs {
  bool wait = false;
  double timeout = 0.0;
  bool json = false;
};

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      out += fmt::format("\\u{:04x}", u);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string_view kindName(lattice::io::SerialPortInfo::Kind kind) {
  switch (kind) {
    case lattice::io::SerialPortInfo::Kind::UsbSerial:
      return "usb";
    case lattice::io::SerialPortInfo::Kind::Uart:
      return "uart";
    case lattice::io::SerialPortInfo::Kind::Other:
      break;
  }
  return "other";
}

void printJson(const std::vector<lattice::io::SerialPortInfo>& ports) {
  fmt::print("[");
  for (std::size_t i = 0; i < ports.size(); ++i) {
    const auto& p = ports[i];
    fmt::print("{}\n  {{\"path\": {}, \"name\": {}, \"kind\": \"{}\", \"driver\": {}", i == 0 ? "" : ",",
               jsonString(p.devicePath), jsonString(p.name), kindName(p.kind), jsonString(p.driver));
    if (p.kind == lattice::io::SerialPortInfo::Kind::UsbSerial)
      fmt::print(", \"vendor_id\": {}, \"product_id\": {}, \"manufacturer\": {}, \"product\": {}, \"serial\": {}",
                 jsonString(p.vendorId), jsonString(p.productId), jsonString(p.manufacturer), jsonString(p.product),
                 jsonString(p.serial));
    fmt::print("}}");
  }
  fmt::print("{}]\n", ports.empty() ? "" : "\n");
}

void runPorts(const PortsArgs& args) {
  std::vector<lattice::io::SerialPortInfo> ports;
  if (args.wait) {
    fmt::print(stderr, "waiting for a USB-serial adapter ({}){}...\n", lattice::io::usbWaitMechanism(),
               args.timeout > 0 ? fmt::format(", up to {:g} s", args.timeout) : std::string());
    lattice::io::UsbWaitOptions wait;
    wait.timeoutSeconds = args.timeout;
    if (lattice::io::waitForUsbSerialPorts(wait).empty())
      throw lattice::Error(lattice::ErrorKind::Serial,
                           fmt::format("no USB-serial adapter appeared within {:g} s; check the cable, and `dmesg` "
                                       "for the adapter's driver binding",
                                       args.timeout));
  }
  ports = lattice::io::listSerialPorts();
  if (args.json) {
    printJson(ports);
    return;
  }
  if (ports.empty()) {
    fmt::print("no serial ports found\n");
    return;
  }
  for (const auto& p : ports) fmt::print("{}\n", p.describe());
}

}  // namespace

namespace lattice::app {

void addPorts(CLI::App& root) {
  auto args = std::make_shared<PortsArgs>();
  auto* cmd = root.add_subcommand(
      "ports",
      "List serial ports (from sysfs): USB-serial adapters with vendor:product, manufacturer, product and "
      "serial number, and built-in UARTs. `--port auto` elsewhere picks the only USB-serial adapter.");
  auto* wait = cmd->add_flag("--wait", args->wait,
                "Wait until a USB-serial adapter is present (returns at once if one already is), then list");
  cmd->add_option("--timeout", args->timeout, "With --wait: give up after this many seconds (exit 5); default: wait for ever")
      ->check(lattice::app::numberIn({0, 1e6}))
      ->needs(wait);
  cmd->add_flag("--json", args->json, "Print a JSON array instead of text");
  cmd->callback([args] { runPorts(*args); });
}

}  // namespace lattice::app
