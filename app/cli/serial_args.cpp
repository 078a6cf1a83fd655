#include "app/cli/serial_args.hpp"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/cli/number_flags.hpp"

namespace lattice::app {

void addSerialOptions(CLI::App* cmd, io::SerialOptions& options, bool portRequired, const std::string& baudDefault) {
  const std::size_t before = cmd->get_options().size();
  auto* port = cmd->add_option("--port", options.port,
                               "Serial port: a device such as /dev/ttyUSB0, or `auto` for the only USB-serial "
                               "adapter (`lattice ports` lists them)");
  if (portRequired) port->required();
  auto* baud = cmd->add_option("--baud", options.baud, "Line speed; match the terminal's setup (9600, 19200, 38400...)")
                   ->check(numberIn({50, 4000000, true}));
  if (baudDefault.empty())
    baud->capture_default_str();
  else
    baud->description(baud->get_description() + " [default: " + baudDefault + "]");
  cmd->add_option_function<std::string>(
         "--flow", [&options](const std::string& text) { options.flow = io::parseFlowControl(text); },
         "Flow control: xonxoff (DC1/DC3, the Tektronix default), rtscts (hardware) or none [xonxoff]")
      ->check(CLI::IsMember(nameList(io::kFlowControlNames)));
  cmd->add_option("--data-bits", options.dataBits, "Data bits per character: 7 or 8")
      ->capture_default_str()
      ->check(numberIn({7, 8, true}));
  cmd->add_option_function<std::string>(
         "--parity", [&options](const std::string& text) { options.parity = io::parseParity(text); },
         "Parity: none, even or odd [none]")
      ->check(CLI::IsMember(nameList(io::kParityNames)));
  cmd->add_option("--stop-bits", options.stopBits, "Stop bits: 1 or 2")
      ->capture_default_str()
      ->check(numberIn({1, 2, true}));
  cmd->add_option("--stall-timeout", options.stallTimeoutSeconds,
                  "Give up (exit 6, resumable) when flow control holds the line this many seconds")
      ->capture_default_str()
      ->check(numberIn({0.001, 1e6}));
  cmd->add_flag("--pace", options.pace,
                "Limit the rate to the baud rate ourselves, for lines that do not (a pty, a network bridge)");
  const std::vector<CLI::Option*> added = cmd->get_options();
  for (std::size_t i = before; i < added.size(); ++i) added[i]->group("Serial line");
}

}  // namespace lattice::app
