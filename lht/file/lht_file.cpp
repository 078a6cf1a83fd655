#include "lht/file/lht_file.hpp"

#include <fmt/format.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "foundation/little_endian.hpp"

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
  void uint(std::uint64_t v, int n) { appendLittleEndian(out, v, n); }
};

// Reads within bounds the caller has already checked.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> b) : in(b) {}
  std::uint64_t uint(int n) {
    const std::uint64_t v = readLittleEndian(in.data() + at, n);
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

// Versions 1 and 2, and version 3's hashed form, held the thesis's chained
// table; the program rebuilds its own caches, so it no longer reads them.
Error retired(const std::string& name, std::uint32_t version) {
  return bad(name, fmt::format("written by an older Lattice (.lht version {}, the chained table), which this "
                               "program no longer reads",
                               version));
}

// "0 thesis, 1 wide, 2 compact"
std::string precisionCodes() {
  std::string out;
  for (const LhtPrecisionInfo& info : kLhtPrecisions)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", static_cast<unsigned>(info.precision), info.name);
  return out;
}

}  // namespace

std::vector<std::uint8_t> serializeLht(const LhtFile& lht) {
  const bool hashed = lht.form() == LhtForm::Hashed;
  const bool inFiles = withForm(
      lht.form(), [](auto i) { return FormAt<decltype(i)::value>::kInFiles; }, [] { return false; });
  if (!inFiles)
    throw Error(ErrorKind::Usage, fmt::format("an {} table is built while rendering and never written to a .lht file; "
                                              "rasterize it as {}",
                                              lhtFormName(lht.form()), lhtFiledFormNames()));
  Writer w;
  w.out.assign(std::begin(kMagic), std::end(kMagic));
  w.u32(hashed ? kLhtVersion : kLhtCompressedVersion);
  for (int a = 0; a < 3; ++a) w.u16(static_cast<std::uint16_t>(lht.box.cells()[a]));
  w.u16(static_cast<std::uint16_t>(lht.precision()));
  w.f64(lht.box.lambda());
  w.f64(lht.box.oversample());
  for (int a = 0; a < 3; ++a) w.f64(lht.box.origin()[a]);
  w.u64(lht.objectHash);
  w.u64(lht.pairs);
  w.u64(lht.hits);
  if (hashed) {
    const LatticeHashTable& t = lht.hashed();
    w.u64(t.entryCount());
    w.u64(t.capacity());
    w.u64(t.capacity());
    w.bytes(t.slotView().data(), t.slotView().size());
  } else {
    // Version 3: the form's own numbers and body.
    std::visit(
        [&](const auto& alternative) {
          const auto& table = formTable(alternative);
          if constexpr (FiledForm<std::decay_t<decltype(table)>>) {
            const LhtBodyHeader h = table.bodyHeader();
            w.u64(h.entries);
            w.u64(h.countA);
            w.u64(h.countB);
            w.u16(static_cast<std::uint16_t>(lht.form()));
            w.u16(h.layout);
            w.u32(0);
            table.appendBody(w.out);
          }
        },
        lht.table);
  }
  w.u64(fnv1a64(w.out));
  return std::move(w.out);
}

namespace {

// What the header says (108 bytes, 116 in version 3), checked on its own and
// against the file's size: magic, version, codes, and every count, before
// anything is allocated.
struct LhtHeader {
  std::uint32_t version = 0;
  std::size_t headerBytes = kLhtHeaderBytes;
  std::array<int, 3> cells{};
  LhtPrecision precision = LhtPrecision::Thesis;
  LhtForm form = LhtForm::Hashed;
  std::uint16_t layout = 0;
  std::size_t stride = 0;
  double lambda = 0, oversample = 0;
  Vec3d origin{0.0};
  std::uint64_t objectHash = 0, pairs = 0, hits = 0, entries = 0, buckets = 0, slots = 0;
  std::uint64_t bodyBytes = 0;  // between the header and the checksum

  // What a version-3 form reads its body with.
  LhtBodyHeader body() const { return {cells, precision, entries, buckets, slots, layout}; }
};

// `prefix` holds the first bytes of the file (up to the header's 108 or
// 116), `size` the file's whole size: enough to refuse junk before reading
// anything else.
LhtHeader parseHeader(std::span<const std::uint8_t> prefix, std::uint64_t size, const std::string& name) {
  if (prefix.size() < sizeof kMagic || std::memcmp(prefix.data(), kMagic, sizeof kMagic) != 0)
    throw bad(name, "not a lattice hash table file (wrong magic number)");
  if (size < kLhtHeaderBytes + 8 || prefix.size() < kLhtHeaderBytes)
    throw bad(name, fmt::format("truncated: {} bytes, shorter than the {}-byte header and checksum", size,
                                kLhtHeaderBytes + 8));
  Reader r(prefix);
  r.at = sizeof kMagic;
  LhtHeader h;
  h.version = static_cast<std::uint32_t>(r.uint(4));
  if (h.version < 1 || h.version > kLhtVersion)
    throw bad(name, fmt::format("format version {} but this program reads versions {} and {}", h.version,
                                kLhtCompressedVersion, kLhtVersion));
  if (h.version < kLhtCompressedVersion) throw retired(name, h.version);
  if (h.version == kLhtCompressedVersion) {
    h.headerBytes = kLhtHeaderBytesV3;
    if (size < kLhtHeaderBytesV3 + 8 || prefix.size() < kLhtHeaderBytesV3)
      throw bad(name, fmt::format("truncated: {} bytes, shorter than the version-3 {}-byte header and checksum", size,
                                  kLhtHeaderBytesV3 + 8));
  }
  for (int a = 0; a < 3; ++a) h.cells[a] = static_cast<int>(r.uint(2));
  const auto precisionCode = static_cast<std::uint16_t>(r.uint(2));
  const std::optional<LhtPrecision> precision = lhtPrecisionFromCode(precisionCode);
  if (!precision)
    throw bad(name, fmt::format("unknown entry precision code {} at byte 18 (this program knows {})", precisionCode,
                                precisionCodes()));
  h.precision = *precision;
  h.stride = LatticeHashTable::slotStride(h.precision);
  h.lambda = r.f64();
  h.oversample = r.f64();
  for (int a = 0; a < 3; ++a) h.origin[a] = r.f64();
  h.objectHash = r.uint(8);
  h.pairs = r.uint(8);
  h.hits = r.uint(8);
  h.entries = r.uint(8);
  h.buckets = r.uint(8);
  h.slots = r.uint(8);
  if (h.version == kLhtCompressedVersion) {
    const auto formCode = static_cast<std::uint16_t>(r.uint(2));
    const auto layoutCode = static_cast<std::uint16_t>(r.uint(2));
    const auto form = lhtFormFromCode(formCode);
    if (!form)
      throw bad(name, fmt::format("unknown LHT form code {} at byte 108 (this program knows {})", formCode,
                                  lhtFiledFormCodes()));
    if (layoutCode > static_cast<std::uint16_t>(PairLayout::Ordered))
      throw bad(name, fmt::format("unknown pair layout code {} at byte 110 (0 symmetric, 1 ordered)", layoutCode));
    if (*form == LhtForm::Hashed) throw retired(name, h.version);  // version 3's hashed form was chained
    h.form = *form;
    h.layout = layoutCode;
    if (h.form != LhtForm::Hashed) {
      const std::uint64_t room = size - h.headerBytes - 8;
      try {
        h.bodyBytes = withForm(
            h.form,
            [&](auto i) -> std::uint64_t {
              if constexpr (FiledForm<FormAt<decltype(i)::value>>)
                return FormAt<decltype(i)::value>::bodyBytes(h.body(), room);
              else
                return 0;
            },
            [] { return std::uint64_t{0}; });
      } catch (const Error& e) {
        throw bad(name, e.what());
      }
      return h;
    }
  }
  // Size before anything else is read (it catches truncation with a clearer
  // message than the checksum would), guarding the multiplication against
  // absurd counts.
  const std::uint64_t maxSlots = (size - h.headerBytes - 8) / h.stride;
  if (h.slots > maxSlots || h.headerBytes + h.slots * h.stride + 8 != size) {
    // slots comes from the file: keep the arithmetic for the message from overflowing.
    const std::string expected = h.slots < (std::uint64_t(1) << 58)
                                     ? fmt::format("{} bytes", h.headerBytes + h.slots * h.stride + 8)
                                     : std::string("an impossible size");
    throw bad(name, fmt::format("truncated or padded: {} bytes, but its header describes {} table slots of {} "
                                "bytes ({})",
                                size, h.slots, h.stride, expected));
  }
  h.bodyBytes = h.slots * h.stride;
  return h;
}

// The header and the table, once the checksum has matched.
LhtFile assemble(const LhtHeader& h, std::vector<std::uint8_t> body, const std::string& name,
                 std::optional<std::uint64_t> expectedObjectHash, std::optional<LhtPrecision> expectedPrecision,
                 std::optional<LhtForm> expectedForm) {
  if (expectedPrecision && *expectedPrecision != h.precision)
    throw bad(name, fmt::format("holds '{}' entries ({} bytes each) but '{}' entries were asked for (the scene's "
                                "`precision` or --lht-precision)",
                                lhtPrecisionName(h.precision), entryBytes(h.precision), lhtPrecisionName(*expectedPrecision)));
  if (expectedForm && *expectedForm != h.form)
    throw bad(name, fmt::format("holds a {} table but a {} one was asked for (the scene's `form` or --lht-form)",
                                lhtFormName(h.form), lhtFormName(*expectedForm)));
  if (expectedObjectHash && *expectedObjectHash != h.objectHash)
    throw bad(name, fmt::format("rasterized from a different object definition (object hash {:016x}, the scene's "
                                "object has {:016x})",
                                h.objectHash, *expectedObjectHash));
  try {
    LhtFile lht;
    lht.version = h.version;
    lht.box = LatticeBox(h.cells, h.lambda, h.oversample, h.origin);
    lht.objectHash = h.objectHash;
    lht.pairs = h.pairs;
    lht.hits = h.hits;
    if (h.form != LhtForm::Hashed) {
      withForm(
          h.form,
          [&](auto i) {
            if constexpr (FiledForm<FormAt<decltype(i)::value>>)
              lht.table.emplace<decltype(i)::value>(FormAt<decltype(i)::value>::fromBody(h.body(), std::move(body)));
          },
          [] {});
    } else {
      lht.table = LatticeHashTable(h.precision, std::move(body), h.buckets, h.entries);
    }
    return lht;
  } catch (const Error& e) {
    throw bad(name, fmt::format("inconsistent contents ({})", e.what()));
  }
}

std::uint64_t readChecksum(std::span<const std::uint8_t> eight) {
  Reader r(eight);
  return r.uint(8);
}

}  // namespace

LhtFile parseLht(std::span<const std::uint8_t> bytes, const std::string& name,
                 std::optional<std::uint64_t> expectedObjectHash, std::optional<LhtPrecision> expectedPrecision,
                 std::optional<LhtForm> expectedForm) {
  const LhtHeader h = parseHeader(bytes.first(std::min(bytes.size(), kLhtHeaderBytesV3)), bytes.size(), name);
  const std::size_t payloadEnd = bytes.size() - 8;
  if (readChecksum(bytes.subspan(payloadEnd)) != fnv1a64(bytes.first(payloadEnd)))
    throw bad(name, "checksum mismatch: the file is corrupted");
  const auto* first = bytes.data() + h.headerBytes;
  return assemble(h, std::vector<std::uint8_t>(first, first + h.bodyBytes), name, expectedObjectHash,
                  expectedPrecision, expectedForm);
}

void writeLhtFile(const std::filesystem::path& path, const LhtFile& lht, AtomicFile::Landing landing) {
  const std::vector<std::uint8_t> bytes = serializeLht(lht);
  writeFileAtomically(path, bytes, landing);
}

LhtFile readLhtFile(const std::filesystem::path& path, std::optional<std::uint64_t> expectedObjectHash,
                    std::optional<LhtPrecision> expectedPrecision, std::optional<LhtForm> expectedForm) {
  // Streamed: the header is checked against the file's size before the
  // table is allocated or read, so junk costs a few bytes of reading.
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open: {}", name, std::strerror(errno)));
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(ErrorKind::Input, fmt::format("{}: not a regular file: {}", name, ec.message()));
  auto readInto = [&](std::uint8_t* to, std::size_t n) {
    in.read(reinterpret_cast<char*>(to), static_cast<std::streamsize>(n));
    if (static_cast<std::size_t>(in.gcount()) != n) throw bad(name, "truncated while reading (the file shrank?)");
  };
  std::uint8_t header[kLhtHeaderBytesV3];
  in.read(reinterpret_cast<char*>(header), kLhtHeaderBytes);
  std::size_t got = static_cast<std::size_t>(in.gcount());
  // Version 3 has 8 more header bytes; the version sits at bytes 8..11.
  if (got == kLhtHeaderBytes && header[8] == kLhtCompressedVersion && !header[9] && !header[10] && !header[11]) {
    in.read(reinterpret_cast<char*>(header + kLhtHeaderBytes), kLhtHeaderBytesV3 - kLhtHeaderBytes);
    got += static_cast<std::size_t>(in.gcount());
  }
  const LhtHeader h = parseHeader(std::span<const std::uint8_t>(header, got), size, name);
  std::vector<std::uint8_t> body(h.bodyBytes);
  readInto(body.data(), body.size());
  std::uint8_t tail[8];
  readInto(tail, sizeof tail);
  if (readChecksum(tail) != fnv1a64(body, fnv1a64(std::span<const std::uint8_t>(header, h.headerBytes))))
    throw bad(name, "checksum mismatch: the file is corrupted");
  return assemble(h, std::move(body), name, expectedObjectHash, expectedPrecision, expectedForm);
}

std::optional<std::uint32_t> retiredLhtVersion(const std::filesystem::path& path) {
  std::uint8_t header[kLhtHeaderBytesV3] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(header), sizeof header);
  if (static_cast<std::size_t>(in.gcount()) < kLhtHeaderBytes || std::memcmp(header, kMagic, sizeof kMagic) != 0)
    return std::nullopt;
  Reader r(std::span<const std::uint8_t>(header, sizeof header));
  r.at = sizeof kMagic;
  const auto version = static_cast<std::uint32_t>(r.uint(4));
  if (version == 1 || version == 2) return version;
  r.at = kLhtHeaderBytes;  // version 3's form code
  if (version == kLhtCompressedVersion && static_cast<std::size_t>(in.gcount()) == sizeof header &&
      lhtFormFromCode(static_cast<std::uint16_t>(r.uint(2))) == LhtForm::Hashed)
    return version;
  return std::nullopt;
}

}  // namespace lattice::lht
