#include "lht/table/compressed_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

#include "foundation/error.hpp"
#include "foundation/little_endian.hpp"
#include "lht/grid/lattice_box.hpp"

namespace lattice::lht {

namespace {

std::uint64_t triangle(std::uint64_t lo, std::uint64_t hi) { return hi * (hi - 1) / 2 + lo; }

}  // namespace

std::uint64_t CompressedTable::bitmapBits(const std::array<int, 3>& cells, PairLayout layout) {
  const std::uint64_t p = BoundaryIndex(cells).count();
  const std::uint64_t bits = layout == PairLayout::Symmetric ? p * (p - 1) / 2 : p * p;
  if (bits > kMaxBitmapBits)
    throw Error(ErrorKind::Input,
                fmt::format("a lattice of {} x {} x {} cells has {} boundary points, a pair space of {} bits, above "
                            "the compressed form's {}; use the hashed form, a larger spacing or a smaller f_lat",
                            cells[0], cells[1], cells[2], p, bits, kMaxBitmapBits));
  return bits;
}

CompressedTable::CompressedTable(const RasterHits& hits, const std::array<int, 3>& cells,
                                 LhtPrecision precision)
    : index_(cells), precision_(precision), layout_(PairLayout::Symmetric), stride_(payloadBytes(precision)) {
  const std::uint64_t p = index_.count();
  // Each hit's ordered pair number, then whether every pair's reverse is there too.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> ordered;  // (i P + o, hit)
  ordered.reserve(hits.size());
  std::uint32_t h = 0;
  for (const RasterHit& hit : hits) {
    const std::uint32_t i = index_.indexOf(hit.in), o = index_.indexOf(hit.out);
    if (i == BoundaryIndex::kNotOnBoundary || o == BoundaryIndex::kNotOnBoundary || i == o)
      throw Error(ErrorKind::Internal, "a rasterized hit lies off the lattice box's surface");
    ordered.emplace_back(std::uint64_t(i) * p + o, h++);
  }
  std::sort(ordered.begin(), ordered.end());
  const bool symmetric = std::all_of(ordered.begin(), ordered.end(), [&](const auto& pair) {
    const std::uint64_t reverse = (pair.first % p) * p + pair.first / p;
    return std::binary_search(ordered.begin(), ordered.end(), std::pair(reverse, std::uint32_t(0)),
                              [](const auto& a, const auto& b) { return a.first < b.first; });
  });
  layout_ = symmetric ? PairLayout::Symmetric : PairLayout::Ordered;
  bits_ = bitmapBits(cells, layout_);
  // The payload order: bit order, and within a symmetric bit lo -> hi first.
  // Rewritten in place (payload position key, hit): a second array of 16
  // bytes a hit was this build's peak (docs/memory.md).
  std::vector<std::pair<std::uint64_t, std::uint32_t>>& order = ordered;
  if (symmetric) {
    for (auto& entry : order) {
      const std::uint64_t i = entry.first / p, o = entry.first % p;
      entry.first = 2 * triangle(std::min(i, o), std::max(i, o)) + (i > o ? 1 : 0);
    }
    std::sort(order.begin(), order.end());
  }
  wordCount_ = (bits_ + 63) / 64;
  body_.assign(bitmapBytes() + order.size() * stride_, 0);
  std::uint8_t* payloads = body_.data() + bitmapBytes();
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint64_t bit = symmetric ? order[k].first / 2 : order[k].first;
    // Bit b of a little-endian word is bit b % 8 of its byte b / 8.
    body_[bit / 8] |= static_cast<std::uint8_t>(1u << (bit % 8));
    encodePayload(hits[order[k].second], precision_, payloads + k * stride_);
  }
  entries_ = hits.size();
  buildRanks();
}

CompressedTable::CompressedTable(const std::array<int, 3>& cells, LhtPrecision precision, PairLayout layout,
                                 std::vector<std::uint8_t> body, std::uint64_t entries)
    : index_(cells), precision_(precision), layout_(layout), stride_(payloadBytes(precision)),
      bits_(bitmapBits(cells, layout)), entries_(entries), wordCount_((bits_ + 63) / 64), body_(std::move(body)) {
  if (body_.size() / stride_ < entries_ || body_.size() != bitmapBytes() + entries_ * stride_)
    throw Error(ErrorKind::Input,
                fmt::format("the compressed LHT's body has {} bytes, its {}-word bitmap and {} entries need {}",
                            body_.size(), wordCount_, entries_, bitmapBytes() + entries_ * stride_));
  // Bits past the pair space would be pairs that do not exist.
  if (bits_ % 64 != 0 && wordCount_ > 0 && (word(wordCount_ - 1) >> (bits_ % 64)) != 0)
    throw Error(ErrorKind::Input, "the compressed LHT's bitmap has bits set past its pair space");
  buildRanks();
}

std::vector<std::uint64_t> CompressedTable::words() const {
  std::vector<std::uint64_t> out(wordCount_);
  for (std::uint64_t w = 0; w < wordCount_; ++w) out[w] = word(w);
  return out;
}

void CompressedTable::buildRanks() {
  ranks_.assign((wordCount_ + kBlockWords - 1) / kBlockWords, 0);
  std::uint64_t count = 0;
  for (std::uint64_t w = 0; w < wordCount_; ++w) {
    if (w % kBlockWords == 0) {
      if (count > 0xFFFFFFFFull) throw Error(ErrorKind::Input, "the compressed LHT has more than 2^32 set bits");
      ranks_[w / kBlockWords] = static_cast<std::uint32_t>(count);
    }
    count += static_cast<std::uint64_t>(std::popcount(word(w)));
  }
  const std::uint64_t expected = layout_ == PairLayout::Symmetric ? 2 * count : count;
  if (expected != entries_)
    throw Error(ErrorKind::Input, fmt::format("the compressed LHT's bitmap holds {} entries, its header says {}",
                                              expected, entries_));
}

// Integers only: the fixed-point leaf calls it per pixel (the objdump test
// in tests/lht/fixed_lattice_test.cpp scans it).
const std::uint8_t* CompressedTable::findPayload(const LatticePoint& in, const LatticePoint& out) const {
  const std::uint64_t i = index_.indexOf(in), o = index_.indexOf(out);
  if (i == BoundaryIndex::kNotOnBoundary || o == BoundaryIndex::kNotOnBoundary || i == o) return nullptr;
  const bool symmetric = layout_ == PairLayout::Symmetric;
  const std::uint64_t bit = symmetric ? (i < o ? triangle(i, o) : triangle(o, i)) : i * index_.count() + o;
  const std::uint64_t w = bit / 64;
  const std::uint64_t bits = word(w);
  const std::uint64_t below = bits & ((std::uint64_t(1) << (bit % 64)) - 1);
  if (!((bits >> (bit % 64)) & 1)) return nullptr;
  std::uint64_t rank = ranks_[w / kBlockWords];
  for (std::uint64_t k = w & ~(kBlockWords - 1); k < w; ++k) rank += static_cast<std::uint64_t>(std::popcount(word(k)));
  rank += static_cast<std::uint64_t>(std::popcount(below));
  const std::uint64_t slot = symmetric ? 2 * rank + (i > o ? 1 : 0) : rank;
  return body_.data() + bitmapBytes() + slot * stride_;
}

std::optional<LhtHit> CompressedTable::find(const LatticePoint& in, const LatticePoint& out) const {
  const std::uint8_t* payload = findPayload(in, out);
  if (!payload) return std::nullopt;
  return toHit(decodePayloadIntegers(payload, precision_));
}

std::vector<std::string> CompressedTable::describe(std::uint64_t hits) const {
  return {
      fmt::format("pair layout:   {} ({} bits)",
                  layout_ == PairLayout::Symmetric ? "symmetric, one bit per unordered pair, two payloads a bit"
                                                   : "ordered, one bit per ordered pair",
                  bits_),
      fmt::format("table bytes:   {} ({:.2f} bytes/entry, {:.2f} per N_iz): bitmap {}, rank directory {}, payloads {} "
                  "({} bytes each)",
                  bytes(), bytesPerEntry(), hits ? double(bytes()) / double(hits) : 0.0, bitmapBytes(), rankBytes(),
                  payloads().size(), payloadBytes(precision_)),
  };
}

LhtBodyHeader CompressedTable::bodyHeader() const {
  LhtBodyHeader h;
  h.cells = index_.cells();
  h.precision = precision_;
  h.entries = entries_;
  h.countA = bits_;
  h.countB = wordCount_;
  h.layout = static_cast<std::uint16_t>(layout_);
  return h;
}

void CompressedTable::appendBody(std::vector<std::uint8_t>& out) const {
  out.reserve(out.size() + body_.size() + 8);  // and the checksum after it
  out.insert(out.end(), body_.begin(), body_.end());
}

std::uint64_t CompressedTable::bodyBytes(const LhtBodyHeader& h, std::uint64_t room) {
  for (int a = 0; a < 3; ++a)
    if (h.cells[a] < 1 || h.cells[a] > kMaxCells)
      throw Error(ErrorKind::Input,
                  fmt::format("lattice cell count {} along {} is outside 1..{}", h.cells[a], "xyz"[a], kMaxCells));
  const std::uint64_t bits = bitmapBits(h.cells, static_cast<PairLayout>(h.layout));
  const std::uint64_t words = (bits + 63) / 64;
  if (h.countA != bits || h.countB != words)
    throw Error(ErrorKind::Input,
                fmt::format("its header gives a bitmap of {} bits in {} words, but a {} x {} x {} lattice's pair "
                            "space has {} bits in {} words",
                            h.countA, h.countB, h.cells[0], h.cells[1], h.cells[2], bits, words));
  const std::uint64_t payload = payloadBytes(h.precision);
  if (words > room / 8 || h.entries > (room - words * 8) / payload || words * 8 + h.entries * payload != room)
    throw Error(ErrorKind::Input, fmt::format("truncated or padded: {} bytes for its body, but its header describes a "
                                              "{}-word bitmap and {} payloads of {} bytes",
                                              room, words, h.entries, payload));
  return room;
}

CompressedTable CompressedTable::fromBody(const LhtBodyHeader& h, std::vector<std::uint8_t> body) {
  return CompressedTable(h.cells, h.precision, static_cast<PairLayout>(h.layout), std::move(body), h.entries);
}

}  // namespace lattice::lht
