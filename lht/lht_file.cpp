#include "lht/lht_file.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <string>

#include "foundation/atomic_file.hpp"
#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

constexpr std::uint8_t kMagic[8] = {'L', 'A', 'T', 'L', 'H', 'T', '\r', '\n'};

class Writer {
 public:
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    out.insert(out.end(), b, b + n);
  }
  void u16(std::uint16_t v) { uint(v, 2); }
  void u32(std::uint32_t v) { uint(v, 4); }
  void u64(std::uint64_t v) { uint(v, 8); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  std::vector<std::uint8_t> out;

 private:
  void uint(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
};

// Reads within bounds the caller has already checked.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> b) : in(b) {}
  std::uint64_t uint(int n) {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= std::uint64_t(in[at + i]) << (8 * i);
    at += static_cast<std::size_t>(n);
    return v;
  }
  double f64() { return std::bit_cast<double>(uint(8)); }
  std::span<const std::uint8_t> in;
  std::size_t at = 0;
};

Error bad(const std::string& name, const std::string& what) {
  return Error(ErrorKind::Input, fmt::format("{}: {}; rebuild it with `lattice rasterize` (or delete it so the "
                                             "scene rasterizes the lattice again)",
                                             name, what));
}

// "0 thesis, 1 wide, 2 compact"
std::string precisionCodes() {
  std::string out;
  for (const LhtPrecisionInfo& info : kLhtPrecisions)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", static_cast<unsigned>(info.precision), info.name);
  return out;
}

}  // namespace

std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

std::uint64_t fnv1a64(std::string_view text) {
  return fnv1a64(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

std::vector<std::uint8_t> serializeLht(const LhtFile& lht) {
  Writer w;
  w.bytes(kMagic, sizeof kMagic);
  w.u32(kLhtVersion);
  for (int a = 0; a < 3; ++a) w.u16(static_cast<std::uint16_t>(lht.box.cells()[a]));
  w.u16(static_cast<std::uint16_t>(lht.table.precision()));
  w.f64(lht.box.lambda());
  w.f64(lht.box.oversample());
  for (int a = 0; a < 3; ++a) w.f64(lht.box.origin()[a]);
  w.u64(lht.objectHash);
  w.u64(lht.pairs);
  w.u64(lht.hits);
  w.u64(lht.table.entryCount());
  w.u64(lht.table.bucketCount());
  w.u64(lht.table.slotCount());
  w.bytes(lht.table.slotBytes().data(), lht.table.slotBytes().size());
  w.u64(fnv1a64(w.out));
  return std::move(w.out);
}

LhtFile parseLht(std::span<const std::uint8_t> bytes, const std::string& name,
                 std::optional<std::uint64_t> expectedObjectHash, std::optional<LhtPrecision> expectedPrecision) {
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw bad(name, "not a lattice hash table file (wrong magic number)");
  if (bytes.size() < kLhtHeaderBytes + 8)
    throw bad(name, fmt::format("truncated: {} bytes, shorter than the {}-byte header and checksum", bytes.size(),
                                kLhtHeaderBytes + 8));
  Reader r(bytes);
  r.at = sizeof kMagic;
  const auto version = static_cast<std::uint32_t>(r.uint(4));
  if (version != 1 && version != kLhtVersion)
    throw bad(name, fmt::format("format version {} but this program reads versions 1 to {}", version, kLhtVersion));
  std::array<int, 3> cells{};
  for (int a = 0; a < 3; ++a) cells[a] = static_cast<int>(r.uint(2));
  const auto precisionCode = static_cast<std::uint16_t>(r.uint(2));
  // Version 1 had only the thesis's entry (and 0 in this field).
  const std::optional<LhtPrecision> precision =
      version == 1 ? std::optional(LhtPrecision::Thesis) : lhtPrecisionFromCode(precisionCode);
  if (!precision)
    throw bad(name, fmt::format("unknown entry precision code {} at byte 18 (this program knows {})", precisionCode,
                                precisionCodes()));
  const std::size_t stride = entryBytes(*precision);
  const double lambda = r.f64();
  const double oversample = r.f64();
  Vec3d origin;
  for (int a = 0; a < 3; ++a) origin[a] = r.f64();
  const std::uint64_t objectHash = r.uint(8);
  const std::uint64_t pairs = r.uint(8);
  const std::uint64_t hits = r.uint(8);
  const std::uint64_t entries = r.uint(8);
  const std::uint64_t buckets = r.uint(8);
  const std::uint64_t slots = r.uint(8);
  // Size first (it catches truncation with a clearer message than the
  // checksum would), guarding the multiplication against absurd counts.
  const std::uint64_t maxSlots = (bytes.size() - kLhtHeaderBytes - 8) / stride;
  if (slots > maxSlots || kLhtHeaderBytes + slots * stride + 8 != bytes.size()) {
    // slots comes from the file: keep the arithmetic for the message from overflowing.
    const std::string expected = slots < (std::uint64_t(1) << 58)
                                     ? fmt::format("{} bytes", kLhtHeaderBytes + slots * stride + 8)
                                     : std::string("an impossible size");
    throw bad(name, fmt::format("truncated or padded: {} bytes, but its header describes {} table slots of {} "
                                "bytes ({})",
                                bytes.size(), slots, stride, expected));
  }
  const std::size_t payloadEnd = bytes.size() - 8;
  Reader tail(bytes);
  tail.at = payloadEnd;
  if (tail.uint(8) != fnv1a64(bytes.first(payloadEnd)))
    throw bad(name, "checksum mismatch: the file is corrupted");
  if (expectedPrecision && *expectedPrecision != *precision)
    throw bad(name, fmt::format("holds '{}' entries ({} bytes each) but '{}' entries were asked for (the scene's "
                                "`precision` or --lht-precision)",
                                lhtPrecisionName(*precision), stride, lhtPrecisionName(*expectedPrecision)));
  if (expectedObjectHash && *expectedObjectHash != objectHash)
    throw bad(name, fmt::format("rasterized from a different object definition (object hash {:016x}, the scene's "
                                "object has {:016x})",
                                objectHash, *expectedObjectHash));
  try {
    LhtFile lht;
    lht.version = version;
    lht.box = LatticeBox(cells, lambda, oversample, origin);
    lht.objectHash = objectHash;
    lht.pairs = pairs;
    lht.hits = hits;
    const auto* first = bytes.data() + kLhtHeaderBytes;
    std::vector<std::uint8_t> table(first, first + slots * stride);
    lht.table = LatticeHashTable(*precision, std::move(table), buckets, entries);
    return lht;
  } catch (const Error& e) {
    throw bad(name, fmt::format("inconsistent contents ({})", e.what()));
  }
}

void writeLhtFile(const std::filesystem::path& path, const LhtFile& lht) {
  const std::vector<std::uint8_t> bytes = serializeLht(lht);
  writeFileAtomically(path, bytes);
}

LhtFile readLhtFile(const std::filesystem::path& path, std::optional<std::uint64_t> expectedObjectHash,
                    std::optional<LhtPrecision> expectedPrecision) {
  const std::vector<std::uint8_t> bytes = readWholeFile(path);
  return parseLht(bytes, path.string(), expectedObjectHash, expectedPrecision);
}

}  // namespace lattice::lht
