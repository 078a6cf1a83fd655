#pragma once
// A serial port opened by path, in the spirit of libserialport's API but our
// own termios code (libserialport refuses ptys, which our tests and
// emulator bridges need). Linux only.
//
// The port is opened non-blocking and exclusive (TIOCEXCL for other
// programs, flock for everyone including root and ourselves); writes never
// block, so the caller (SerialSink) owns every timeout.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "io/serial_options.hpp"

namespace lattice::io {

class SerialPort {
 public:
  // Error(Serial) with the path and a fix: no such port, permission denied
  // (dialout group), busy (another program has it), not a serial port.
  explicit SerialPort(std::string path);
  ~SerialPort();
  SerialPort(SerialPort&& other) noexcept;
  SerialPort& operator=(SerialPort&& other) noexcept;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Raw mode plus the line settings. Error(Usage) for impossible settings,
  // Error(Serial) when the driver refuses one (some refuse odd baud rates).
  void configure(const SerialOptions& options);

  enum class Status { Progress, WouldBlock, HangUp };
  struct WriteResult {
    std::size_t written = 0;
    Status status = Status::Progress;
  };
  // Hands the kernel what it takes now; never blocks.
  WriteResult writeSome(std::span<const std::uint8_t> bytes);

  enum class Wait { Writable, Timeout, HangUp };
  // Waits up to timeoutMs for room in the output queue (EINTR restarts).
  Wait waitWritable(int timeoutMs);

  // Bytes the kernel accepted but has not yet shifted out (TIOCOUTQ); 0 when
  // the driver does not say. A pty always says 0: its bytes go straight to the peer.
  std::size_t outputQueued() const;
  // Throws away queued output (TCOFLUSH) so it is never sent late.
  void discardOutput();
  // tcdrain: returns when the last queued byte has left. Call only when the
  // queue is known to be moving (it blocks without a timeout).
  void drainQueued();
  // Throws away anything the terminal sent us before we started.
  void discardInput();

  void close();
  bool isOpen() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  // A Unix98 pty slave (/dev/pts/N): no UART, so no baud pacing and no line format.
  bool isPty() const { return isPty_; }

 private:
  std::string path_;
  int fd_ = -1;
  bool isPty_ = false;
};

// True for rates with a Bnnn constant (set with cfsetspeed); others need termios2.
bool isStandardBaud(int baud);

}  // namespace lattice::io
