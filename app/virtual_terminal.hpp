#pragma once
// A terminal to send to without one: a pseudo-terminal whose far side is a
// device's emulator, so `lattice send STREAM --port virtual:tek4125` goes
// through the same serial code as a real line (the port opened by path, raw
// mode, XON/XOFF, stalls, `!REP` answers) and ends in the screen the
// emulator drew.
//
// Method and tunables: a thread on the pty's master side plays the terminal.
// It takes bytes into an input buffer of kInputBufferBytes and draws them
// (feeds the emulator) at the line's character rate (baud / bits per
// character, foundation/line_timing.hpp), as a terminal that keeps up with
// its line would. With --flow xonxoff it sends DC3 when the buffer is
// three-quarters full and DC1 once it is down to a quarter (the terminal's
// "flagging"); with rtscts or none it simply stops reading when the buffer
// is full, which on a pty blocks the sender as a lowered CTS would (a pty
// has no modem lines). A device that paces with report requests (the 4027's
// `!REP`) is answered with a CR once the request has been drawn.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "devices/device.hpp"
#include "io/pty.hpp"
#include "io/serial_options.hpp"

namespace lattice::app {

class VirtualTerminal {
 public:
  static constexpr std::size_t kInputBufferBytes = 4096;

  // `line`: the baud, line format and flow control the terminal is set to.
  VirtualTerminal(devices::Device device, const io::SerialOptions& line);
  ~VirtualTerminal();
  VirtualTerminal(const VirtualTerminal&) = delete;
  VirtualTerminal& operator=(const VirtualTerminal&) = delete;

  // The path the sender opens as its serial port.
  const std::string& portPath() const { return pty_.slavePath(); }
  // After the sender opened the port: from now on its closing is the end of the stream.
  void senderConnected() { pty_.releaseSlave(); }
  // Waits (at most timeoutSeconds) for the sender to close the line, draws
  // what is still buffered and returns the emulator; Error(Stalled) if the
  // line stays open.
  StreamDecoder& finish(double timeoutSeconds);

 private:
  void run();

  devices::Device device_;
  io::SerialOptions line_;
  io::PtyPair pty_;
  std::unique_ptr<StreamDecoder> emulator_;
  std::vector<std::uint8_t> drawn_;  // every byte drawn: where report requests are found
  std::size_t answeredUpTo_ = 0;     // just past the last request answered
  std::atomic<bool> closed_{false};  // the sender hung up and the buffer is drawn
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace lattice::app
