#pragma once
// The far end of a pty for serial tests: a thread that reads everything the
// sink sends (as a terminal would), and lets the test send XOFF/XON or hang
// up. Every wait is bounded so a broken sink fails a test instead of hanging it.
#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "io/pty.hpp"

namespace lattice::testing {

constexpr std::uint8_t kXon = 0x11;   // DC1
constexpr std::uint8_t kXoff = 0x13;  // DC3

class PtyPeer {
 public:
  explicit PtyPeer(io::PtyPair& pty) : pty_(pty) {
    ::fcntl(pty_.masterFd(), F_SETFL, ::fcntl(pty_.masterFd(), F_GETFL) | O_NONBLOCK);
    // Packet mode: each read starts with a status byte, and the kernel
    // reports TIOCPKT_STOP / TIOCPKT_START when the slave's output is
    // stopped or restarted by flow control, so tests can wait for the
    // XOFF to take effect instead of guessing with sleeps.
    int on = 1;
    ::ioctl(pty_.masterFd(), TIOCPKT, &on);
    reader_ = std::thread([this] { readLoop(); });
  }
  ~PtyPeer() { stop(); }
  PtyPeer(const PtyPeer&) = delete;
  PtyPeer& operator=(const PtyPeer&) = delete;

  void send(std::uint8_t byte) {
    // The master is non-blocking but its buffer is empty in these tests; a
    // short write would be a test bug, so retry briefly.
    for (int tries = 0; tries < 100; ++tries) {
      if (::write(pty_.masterFd(), &byte, 1) == 1) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  // Stop reading once `limit` bytes have arrived, as a terminal busy drawing
  // would: the pty fills and the sender blocks. release() reads on.
  void holdAt(std::size_t limit) { limit_ = limit; }
  void release() { limit_ = SIZE_MAX; }

  // Holds the sender at `at` bytes, sends XOFF while it is blocked, then
  // reads on: deterministic, unlike racing an XOFF against a fast writer.
  // Call holdAt(at) first from the test's thread, before the sender starts,
  // so the hold cannot come too late.
  bool stopSenderAt(std::size_t at) {
    holdAt(at);
    bool reached = waitFor(at);
    send(kXoff);
    bool stopped = waitForStop();
    release();
    return reached && stopped;
  }

  // True once the kernel reported the slave's output stopped (XOFF taken).
  bool waitForStop(double seconds = 5.0) const {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!stopped_) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
  }
  bool outputStopped() const { return stopped_; }

  std::size_t received() const {
    std::lock_guard lock(mutex_);
    return data_.size();
  }
  std::vector<std::uint8_t> data() const {
    std::lock_guard lock(mutex_);
    return data_;
  }
  // True once at least n bytes arrived; false after the timeout.
  bool waitFor(std::size_t n, double seconds = 5.0) const {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (received() < n) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
  }
  // Waits until nothing has arrived for `quiet` seconds (bytes in flight landed).
  void settle(double quiet = 0.15) const {
    std::size_t last = received();
    for (int i = 0; i < 100; ++i) {
      std::this_thread::sleep_for(std::chrono::duration<double>(quiet));
      std::size_t now = received();
      if (now == last) return;
      last = now;
    }
  }
  void stop() {
    stop_ = true;
    if (reader_.joinable()) reader_.join();
  }

 private:
  void readLoop() {
    std::vector<std::uint8_t> buffer(16384);
    while (!stop_) {
      // The status byte plus what the hold allows; while held, one-byte
      // reads still pick up status packets but take no data.
      std::size_t room = std::min(buffer.size() - 1, limit_ - std::min<std::size_t>(limit_, received()));
      pollfd entry{pty_.masterFd(), POLLIN, 0};
      if (::poll(&entry, 1, 10) <= 0) continue;
      if (room == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      ssize_t n = ::read(pty_.masterFd(), buffer.data(), room + 1);
      if (n <= 0) {
        // The master was closed (hang-up test) or the slave side went away.
        if (n < 0 && errno == EAGAIN) continue;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        continue;
      }
      if (buffer[0] != TIOCPKT_DATA) {
        if (buffer[0] & TIOCPKT_STOP) stopped_ = true;
        if (buffer[0] & TIOCPKT_START) stopped_ = false;
        continue;
      }
      std::lock_guard lock(mutex_);
      data_.insert(data_.end(), buffer.begin() + 1, buffer.begin() + n);
    }
  }

  io::PtyPair& pty_;
  std::thread reader_;
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> limit_{SIZE_MAX};
  std::atomic<bool> stopped_{false};
  mutable std::mutex mutex_;
  std::vector<std::uint8_t> data_;
};

inline std::vector<std::uint8_t> pseudoRandomBytes(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> bytes(n);
  for (auto& b : bytes) b = static_cast<std::uint8_t>(rng() >> 24);
  return bytes;
}

}  // namespace lattice::testing
