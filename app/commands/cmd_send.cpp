// `lattice send STREAM --port ...`: play a stored command stream to a
// terminal over a serial line, resumably (app/commands/send_file.hpp). See
// docs/serial.md.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>

#include "app/commands/commands.hpp"
#include "app/commands/send_file.hpp"
#include "app/cli/number_flags.hpp"
#include "app/cli/serial_args.hpp"
#include "devices/device_table.hpp"

namespace lattice::app {

void addSend(CLI::App& root) {
  auto args = std::make_shared<SendArgs>();
  auto* cmd = root.add_subcommand(
      "send",
      "Send a stored device command stream (e.g. a Tektronix 4125/4027 stream file) to a terminal over a serial line, through "
      "flow control, with a progress bar. A file that is not a terminal's stream (a PNG, a scene, noise) is "
      "refused with exit 3 before a byte goes out (--raw sends it anyway). If the line stalls (exit 6) or hangs up "
      "(exit 7), or the send is interrupted (Ctrl-C: status 130), it prints how many bytes went out and the "
      "`--resume` command that continues exactly there.");
  // Read (and refused with exit 3, naming the file) by readStreamHead and readFileUpTo, not by a CLI check.
  cmd->add_option("STREAM", args->stream, "The command stream file to send")->required();
  lattice::app::addSerialOptions(cmd, args->serial, /*portRequired=*/true,
                                 "9600; for virtual:DEVICE, the device profile's rate");
  cmd->get_option("--port")->description(
      "Serial port: a device such as /dev/ttyUSB0, `auto` for the only USB-serial adapter (`lattice ports` lists "
      "them), or virtual:tek4125 / virtual:tek4027 for our emulator on a pseudo-terminal (docs/serial.md)");
  cmd->add_option("--device", args->device,
                  "The terminal the stream is for (the stream must look like its stream, unless --raw), and how "
                  "it paces the stream by answering requests: with tek4027, "
                  "a stream paced with `!REP 00` (pacing=report or auto) is sent one record at a time, each after "
                  "the terminal's answer to the one before (--stall-timeout bounds each wait)")
      ->check(CLI::IsMember(lattice::devices::deviceNames()));
  cmd->add_option("--set", args->settings,
                  "With --device: override a profile assumption, key=value (repeatable), as for render");
  cmd->add_option("--resume", args->resume, "Start at this byte offset, as printed by a failed send")
      ->check(lattice::app::numberIn({0, 9.0e15, true}));
  cmd->add_option("-o,--output", args->screen,
                  "With --port virtual:DEVICE: the PNG of the screen the virtual terminal drew (default "
                  "virtual-DEVICE.png)");
  cmd->add_flag("--raw", args->raw,
                "Send the file even if it does not look like a terminal's command stream (without it, a PNG, a "
                "scene, an empty file, noise or another terminal's stream is refused with exit 3 before a byte "
                "goes out)");
  cmd->callback([args, cmd] {
    SendArgs send = *args;
    send.baudGiven = cmd->count("--baud") > 0;
    send.screenGiven = cmd->count("--output") > 0;
    send.force = cmd->count("--force") > 0;
    runSend(send);
  });
}

}  // namespace lattice::app
