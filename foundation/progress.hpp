#pragma once
// A progress bar on stderr for long work (render, rasterize, send). It draws
// only when stderr is a terminal, so logs and CI output stay clean; it is
// thread-safe (workers call advance()) and redraws at most ~10 times a second.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

#include "foundation/threads.hpp"

namespace lattice {

class Progress {
 public:
  // total: units of work; unit: label shown after the counts ("rows", "B").
  Progress(std::string label, std::uint64_t total, std::string unit = "");
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::uint64_t units = 1);
  void set(std::uint64_t done);
  void finish();  // draws 100% and a newline (if drawing at all)
  bool enabled() const { return enabled_; }
  // Force drawing on or off (tests, --quiet, --progress).
  void setEnabled(bool on) { enabled_ = on; }

 private:
  void draw(bool final);

  std::string label_;
  std::string unit_;
  std::uint64_t total_;
  std::atomic<std::uint64_t> done_{0};
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDraw_;
  Mutex drawMutex_;
};

}  // namespace lattice
