#include "devices/apollo_sim/gpr_journal.hpp"

#include <fmt/format.h>

#include "devices/work_budget.hpp"
#include "foundation/error.hpp"

namespace lattice::apollo {
namespace {

void putU16(std::vector<std::uint8_t>& out, int v) {
  out.push_back(static_cast<std::uint8_t>(v & 0xFF));
  out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
}

std::size_t u16At(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::size_t>(bytes[at]) | static_cast<std::size_t>(bytes[at + 1]) << 8;
}

}  // namespace

GprJournalWriter::GprJournalWriter(ByteSink& out, const ApolloProfile& profile) : out_(out), profile_(profile) {
  out_.write(kGprJournalHeader);
}

GprDisplayCharacteristics GprJournalWriter::inqDispCharacteristics() const { return characteristicsOf(profile_); }

void GprJournalWriter::acquireDisplay() {
  record_.assign({'A'});
  out_.write(record_);
}

void GprJournalWriter::releaseDisplay() {
  record_.assign({'R'});
  out_.write(record_);
}

void GprJournalWriter::setColorMap(int start, std::span<const std::uint32_t> values) {
  record_.assign({'M'});
  putU16(record_, start);
  putU16(record_, static_cast<int>(values.size()));
  for (std::uint32_t v : values) {
    const Rgb8 c = unpackRgb(v);
    record_.insert(record_.end(), {c.r, c.g, c.b});
  }
  out_.write(record_);
}

void GprJournalWriter::writePixels(std::span<const std::uint32_t> values, const GprWindow& window) {
  record_.assign({'W'});
  for (int v : {window.x, window.y, window.width, window.height}) putU16(record_, v);
  for (std::uint32_t v : values) record_.push_back(static_cast<std::uint8_t>(v));
  out_.write(record_);
}

void GprJournalWriter::clear(std::uint32_t index) {
  record_.assign({'K', static_cast<std::uint8_t>(index)});
  out_.write(record_);
}

GprJournalDecoder::GprJournalDecoder(const ApolloProfile& profile) : profile_(profile) {
  display_.init(GprDisplayMode::Borrow, profile_);
}

std::size_t GprJournalDecoder::headLength(std::uint8_t op) {
  return op == 'M' ? 5 : op == 'W' ? 9 : op == 'K' ? 2 : 1;
}

bool GprJournalDecoder::fits() const {
  const std::span<const std::uint8_t> p(pending_);
  if (p[0] == 'M') return u16At(p, 1) + u16At(p, 3) <= static_cast<std::size_t>(profile_.colorMapEntries());
  if (p[0] == 'W')
    return u16At(p, 1) + u16At(p, 5) <= static_cast<std::size_t>(profile_.width) &&
           u16At(p, 3) + u16At(p, 7) <= static_cast<std::size_t>(profile_.height);
  return true;
}

long GprJournalDecoder::recordLength() const {
  const std::span<const std::uint8_t> p(pending_);
  switch (p[0]) {
    case 'A':
    case 'R':
      return 1;
    case 'K':
      return 2;
    case 'M':
      return p.size() < 5 ? 0 : static_cast<long>(5 + 3 * u16At(p, 3));
    case 'W':
      return p.size() < 9 ? 0 : static_cast<long>(9 + u16At(p, 5) * u16At(p, 7));
    default:
      return -1;
  }
}

void GprJournalDecoder::feed(std::span<const std::uint8_t> bytes) {
  report_.bytes += bytes.size();
  snapshotStale_ = true;
  for (std::uint8_t b : bytes) {
    if (headerSeen_ < sizeof kGprJournalHeader) {
      if (b == kGprJournalHeader[headerSeen_]) {
        ++headerSeen_;
        continue;
      }
      ++report_.malformed;  // not a journal, or a cut header: read records anyway
      headerSeen_ = sizeof kGprJournalHeader;
    }
    if (skip_ > 0) {  // the rest of a record refused by its head
      --skip_;
      continue;
    }
    pending_.push_back(b);
    const long length = recordLength();
    if (length < 0) {
      ++report_.unknownCommands;
      ++report_.unknownByName[fmt::format("0x{:02x}", pending_[0])];
      pending_.clear();
      continue;
    }
    // The head alone says whether a record fits the screen and colour map, so
    // a record that does not is dropped as it arrives, never buffered.
    if (length > 0 && pending_.size() == headLength(pending_[0]) && !fits()) {
      ++report_.malformed;
      skip_ = static_cast<std::size_t>(length) - pending_.size();
      pending_.clear();
      continue;
    }
    if (length > 0 && pending_.size() == static_cast<std::size_t>(length)) {
      replay(pending_);
      pending_.clear();
    }
  }
}

void GprJournalDecoder::replay(std::span<const std::uint8_t> r) {
  const bool drawable = display_.acquired();
  switch (r[0]) {
    case 'A':
      if (display_.acquired()) return void(++report_.malformed);
      display_.acquireDisplay();
      break;
    case 'R':
      if (!display_.acquired()) return void(++report_.malformed);
      display_.releaseDisplay();
      break;
    case 'K':  // two bytes that clear the whole screen: charged like a Tek page clear
      if (!drawable) return void(++report_.malformed);
      if (chargePixelWork(report_, std::uint64_t(profile_.width) * std::uint64_t(profile_.height)))
        display_.clear(r[1]);
      break;
    case 'M': {
      const std::size_t start = u16At(r, 1), n = u16At(r, 3);
      if (!drawable) return void(++report_.malformed);
      std::vector<std::uint32_t> values(n);
      for (std::size_t i = 0; i < n; ++i) values[i] = packRgb(Rgb8{r[5 + 3 * i], r[6 + 3 * i], r[7 + 3 * i]});
      display_.setColorMap(static_cast<int>(start), values);
      break;
    }
    case 'W': {
      const GprWindow w{static_cast<int>(u16At(r, 1)), static_cast<int>(u16At(r, 3)), static_cast<int>(u16At(r, 5)),
                        static_cast<int>(u16At(r, 7))};
      if (!drawable) return void(++report_.malformed);
      std::vector<std::uint32_t> values(r.begin() + 9, r.end());
      display_.writePixels(values, w);
      break;
    }
  }
  ++report_.commands;
}

void GprJournalDecoder::finish() {
  if (!pending_.empty() || skip_ > 0) ++report_.malformed;  // a record cut off by the end
  pending_.clear();
  skip_ = 0;
}

const IndexedImage& GprJournalDecoder::image() const {
  if (snapshotStale_) {
    snapshot_ = display_.snapshot();
    snapshotStale_ = false;
  }
  return snapshot_;
}

}  // namespace lattice::apollo
