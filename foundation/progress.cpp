#include "foundation/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace lattice {

Progress::Progress(std::string label, std::uint64_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total == 0 ? 1 : total),
      enabled_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

Progress::~Progress() {
  if (!finished_) finish();
}

void Progress::advance(std::uint64_t units) {
  done_.fetch_add(units, std::memory_order_relaxed);
  if (enabled_) draw(false);
}

void Progress::set(std::uint64_t done) {
  done_.store(done, std::memory_order_relaxed);
  if (enabled_) draw(false);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!enabled_) return;
  done_.store(total_);
  draw(true);
  std::fputc('\n', stderr);
}

void Progress::draw(bool final) {
  std::unique_lock lock(drawMutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // another thread is drawing; skip this frame
  auto now = std::chrono::steady_clock::now();
  if (!final && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  std::uint64_t done = std::min<std::uint64_t>(done_.load(std::memory_order_relaxed), total_);
  double fraction = static_cast<double>(done) / static_cast<double>(total_);
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double eta = fraction > 0 ? elapsed / fraction - elapsed : 0.0;
  constexpr int kWidth = 30;
  int filled = static_cast<int>(fraction * kWidth);
  std::string bar(static_cast<size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::string rate = elapsed > 0 ? fmt::format("{:.0f} {}/s", static_cast<double>(done) / elapsed, unit_) : "";
  std::fprintf(stderr, "\r%s [%s] %3.0f%% %llu/%llu %s  %s  ETA %.0fs \x1b[K", label_.c_str(), bar.c_str(),
               fraction * 100.0, static_cast<unsigned long long>(done),
               static_cast<unsigned long long>(total_), unit_.c_str(), rate.c_str(), final ? 0.0 : eta);
  std::fflush(stderr);
}

}  // namespace lattice
