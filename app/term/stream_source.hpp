#pragma once
// A recorded stream played as the line delivered it: at the baud rate's
// character rate (baud / bits a character, foundation/line_timing.hpp), so a
// person sees what someone at the real terminal saw, when they saw it; or,
// unpaced, as fast as the terminal decodes it (the benchmark's case).
//
// Method: the bytes owed are the time since the start times the character
// rate; read() hands them over, and timeoutMs() says when the next slice is
// due (kSliceMs: finer slices would only wake the process more often than a
// screen refresh can show). Keys and answers are dropped: a recording hears nothing.
#include <chrono>

#include "app/term/term_source.hpp"
#include "foundation/line_timing.hpp"

namespace lattice::app {

class StreamSource final : public TermSource {
 public:
  static constexpr int kSliceMs = 10;
  static constexpr std::size_t kUnpacedChunk = 65536;

  // charactersPerSecond <= 0: unpaced. Error(Input) for an unreadable file or
  // one over kMaxStreamBytes.
  StreamSource(const std::string& path, double charactersPerSecond);
  int fd() const override { return -1; }
  bool read(std::vector<std::uint8_t>& out) override;
  void write(std::span<const std::uint8_t>) override {}
  int timeoutMs() const override;
  std::string endReason() const override;

 private:
  std::size_t owed() const;

  std::string path_;
  std::vector<std::uint8_t> bytes_;
  std::size_t played_ = 0;
  double rate_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace lattice::app
