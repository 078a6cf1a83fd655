#pragma once
// The compressed LHT (thesis sec. 5.2.1: "the pairs are enumerable, so the
// key need not be stored"): no key, no overflow chain, exact membership.
//
// Method and tunables:
// * Pair space. Boundary points are numbered by lht/grid/boundary_index.hpp
//   (P of them). The rasterizer's hits are symmetric in practice ((p_i, p_o)
//   hits exactly when (p_o, p_i) does: the same segment), so the bitmap has
//   one bit per unordered pair {i, o}, i < o, at o (o - 1) / 2 + i
//   (P (P - 1) / 2 bits), and each set bit owns two payloads, i -> o first.
//   A hit list that is not symmetric (it has never been seen, but rounding
//   could make one) gets the `ordered` layout instead: one bit per ordered
//   pair at i P + o (P^2 bits), one payload per bit. Either way a pair whose
//   bit is clear has no entry, so a ray that misses can never get a hit.
// * Rank directory: a 32-bit count of the set bits before every 512-bit
//   block (8 words; 1/16 of the bitmap), so the rank of a bit is one count
//   plus at most 8 popcounts. It is derived from the bitmap when a table is
//   built or read, never stored in a file.
// * Payloads: payloadBytes(precision) each (4, 6 or 3 bytes), the entry
//   precision's bits unchanged, in bit order; identical bytes to the hashed
//   table's payloads, so pictures are identical.
// * Held as the .lht body is laid out (the words little-endian, then the
//   payloads) in one array, so reading a file adopts its body, and writing
//   one copies it out.
// * kMaxBitmapBits = 2^34 (2 GiB of bitmap): a pair space beyond it is
//   refused, naming the lattice's size. The table 1 shapes need under 2^23.
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "foundation/little_endian.hpp"
#include "lht/grid/boundary_index.hpp"
#include "lht/table/entry_codec.hpp"
#include "lht/table/lht_form.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

enum class PairLayout : std::uint16_t {
  Symmetric = 0,  // one bit per unordered pair, two payloads per bit
  Ordered = 1,    // one bit per ordered pair, one payload per bit
};

class CompressedTable {
 public:
  // Its entry in the form list (lht/table/table_forms.hpp).
  static constexpr std::string_view kFormName = "compressed";
  static constexpr std::string_view kFormSummary = "compressed (no key, no chain: a rank bitmap over the pair space)";
  static constexpr bool kInFiles = true;
  static CompressedTable fromHits(const RasterHits& hits, const std::array<int, 3>& cells, LhtPrecision precision) {
    return CompressedTable(hits, cells, precision);
  }
  std::vector<std::string> describe(std::uint64_t hits) const;

  // Its .lht body (version 3): countA the bitmap's bits, countB its words,
  // layout the PairLayout; the body the words (8 bytes each, little-endian),
  // then the payloads.
  LhtBodyHeader bodyHeader() const;
  void appendBody(std::vector<std::uint8_t>& out) const;
  // The body's bytes (`room` is what the file has for it), or Error(Input).
  static std::uint64_t bodyBytes(const LhtBodyHeader& header, std::uint64_t room);
  static CompressedTable fromBody(const LhtBodyHeader& header, std::vector<std::uint8_t> body);

  static constexpr std::uint64_t kMaxBitmapBits = std::uint64_t(1) << 34;
  static constexpr std::uint64_t kBlockWords = 8;  // rank directory granularity (512 bits)

  // An empty table of a one-cell box (28 pair bits, one word).
  CompressedTable()
      : CompressedTable({1, 1, 1}, LhtPrecision::Thesis, PairLayout::Symmetric, std::vector<std::uint8_t>(8, 0), 0) {}
  // From rasterized hits (distinct keys, all on the box's surface) of a box of `cells`.
  CompressedTable(const RasterHits& hits, const std::array<int, 3>& cells, LhtPrecision precision);
  // Adopts a file's body (the bitmap's words, little-endian, then the
  // payloads) as it is, without a copy; throws lattice::Error(Input) when its
  // size or the number of set bits disagrees with `entries`.
  CompressedTable(const std::array<int, 3>& cells, LhtPrecision precision, PairLayout layout,
                  std::vector<std::uint8_t> body, std::uint64_t entries);

  // The bits of the pair space of a box (throws Error(Input) above kMaxBitmapBits).
  static std::uint64_t bitmapBits(const std::array<int, 3>& cells, PairLayout layout);

  // The payload of (in, out), payloadBytes(precision()) bytes; null if absent.
  const std::uint8_t* findPayload(const LatticePoint& in, const LatticePoint& out) const;
  std::optional<LhtHit> find(const LatticePoint& in, const LatticePoint& out) const;

  LhtPrecision precision() const { return precision_; }
  PairLayout layout() const { return layout_; }
  std::uint64_t entryCount() const { return entries_; }
  // The bitmap's words (a copy: they are held as the body's bytes).
  std::vector<std::uint64_t> words() const;
  std::span<const std::uint8_t> payloads() const {
    return std::span(body_).subspan(static_cast<std::size_t>(bitmapBytes()));
  }
  std::uint64_t bitmapBytes() const { return wordCount_ * sizeof(std::uint64_t); }
  std::uint64_t rankBytes() const { return ranks_.size() * sizeof(std::uint32_t); }
  // Everything held: bitmap, rank directory, payloads.
  std::uint64_t bytes() const { return rankBytes() + body_.size(); }
  double bytesPerEntry() const { return entries_ ? double(bytes()) / double(entries_) : 0.0; }

 private:
  void buildRanks();
  // Bitmap word w, from its little-endian bytes (one load on a little-endian host).
  std::uint64_t word(std::uint64_t w) const {
    if constexpr (std::endian::native == std::endian::little) {
      std::uint64_t value;
      std::memcpy(&value, body_.data() + 8 * w, sizeof value);
      return value;
    } else {
      return readLittleEndian(body_.data() + 8 * w, 8);
    }
  }

  BoundaryIndex index_;
  LhtPrecision precision_;
  PairLayout layout_;
  std::size_t stride_;
  std::uint64_t bits_ = 0;
  std::uint64_t entries_ = 0;
  std::uint64_t wordCount_ = 0;
  // The .lht body itself: the bitmap's words, little-endian, then the
  // payloads. One array, so a table read from a file adopts the bytes read
  // instead of copying them: the copy beside the body was a peak of a
  // render from a cache (docs/memory.md).
  std::vector<std::uint8_t> body_;
  std::vector<std::uint32_t> ranks_;  // set bits before each block of kBlockWords words
};

}  // namespace lattice::lht
