// The banded PNG encoder (method and reasons in png_encoder.hpp).
#include "io/png_encoder.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>

#include "foundation/error.hpp"
#include "foundation/threads.hpp"
#include "io/adler32.hpp"

namespace lattice::io {
namespace {

constexpr std::size_t kWindowBytes = 32768;  // deflate's window (RFC 1951): the most a dictionary can reach back
// A band's dictionary: whole rows of at least this many bytes. zlib hashes
// every dictionary byte, and past the row or two above (the matches a
// picture's vertical runs make) the rest of the window bought 0.1 % of the
// file for 6 % of deflate's time (bench/results/2026-12-05-lead.md).
constexpr std::size_t kDictionaryBytes = 8192;

int paeth(int a, int b, int c) {  // W3C PNG 9.4: the neighbour nearest a + b - c
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// One row as PNG stores it: the filter byte, then the filtered samples.
// `above` is the previous row unfiltered, or null for the first row.
void filterRow(PngFilter filter, std::size_t bpp, const std::uint8_t* row, const std::uint8_t* above,
               std::size_t rowBytes, std::uint8_t* out) {
  *out++ = static_cast<std::uint8_t>(filter);
  switch (filter) {
    case PngFilter::None: std::memcpy(out, row, rowBytes); return;
    case PngFilter::Sub:
      for (std::size_t i = 0; i < rowBytes; ++i) out[i] = static_cast<std::uint8_t>(row[i] - (i >= bpp ? row[i - bpp] : 0));
      return;
    case PngFilter::Up:
      for (std::size_t i = 0; i < rowBytes; ++i) out[i] = static_cast<std::uint8_t>(row[i] - (above ? above[i] : 0));
      return;
    case PngFilter::Paeth:
      for (std::size_t i = 0; i < rowBytes; ++i) {
        const int a = i >= bpp ? row[i - bpp] : 0, b = above ? above[i] : 0;
        const int c = above && i >= bpp ? above[i - bpp] : 0;
        out[i] = static_cast<std::uint8_t>(row[i] - paeth(a, b, c));
      }
      return;
  }
}

void appendBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  out.insert(out.end(), {std::uint8_t(v >> 24), std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)});
}

// A chunk (W3C PNG 5.3): length, type, data (in up to three pieces), CRC-32
// of type and data; written piece by piece so no copy of the data is made.
void writeChunk(ByteSink& out, const char* type, std::span<const std::uint8_t> head,
                std::span<const std::uint8_t> data = {}, std::span<const std::uint8_t> tail = {}) {
  std::vector<std::uint8_t> frame;
  appendBigEndian(frame, static_cast<std::uint32_t>(head.size() + data.size() + tail.size()));
  frame.insert(frame.end(), type, type + 4);
  uLong crc = crc32_z(crc32(0, nullptr, 0), frame.data() + 4, 4);
  out.write(frame);
  for (std::span<const std::uint8_t> piece : {head, data, tail}) {
    if (piece.empty()) continue;  // crc32_z with no buffer returns the initial value, not crc
    crc = crc32_z(crc, piece.data(), piece.size());
    out.write(piece);
  }
  frame.clear();
  appendBigEndian(frame, static_cast<std::uint32_t>(crc));
  out.write(frame);
}

struct Band {
  std::vector<std::uint8_t> deflated;
  uLong adler = 1;
  std::size_t filteredBytes = 0;
};

struct Layout {
  std::size_t bpp, rowBytes, rowsPerBand, bands, rowsBefore;  // rowsBefore: rows that fill the dictionary
};

// One worker's deflate stream, reset for each band (deflateReset keeps the
// level, strategy and the memory zlib allocated), and its row buffers.
class BandDeflater {
 public:
  explicit BandDeflater(const PngEncoding& encoding) {
    if (deflateInit2(&z_, encoding.level, Z_DEFLATED, -15, 8, encoding.runLength ? Z_RLE : Z_DEFAULT_STRATEGY) != Z_OK)
      throw Error(ErrorKind::Internal, "PNG encoding: zlib's deflateInit2 failed");
  }
  ~BandDeflater() { deflateEnd(&z_); }
  BandDeflater(const BandDeflater&) = delete;
  BandDeflater& operator=(const BandDeflater&) = delete;

  // Filters the rows before the band that fill the dictionary, then deflates
  // the band's own rows one at a time, sync-flushed (the last band: finished).
  void run(const PngPixels& px, const PngEncoding& encoding, const Layout& layout, std::size_t band, Band& out) {
    const std::size_t first = band * layout.rowsPerBand;
    const std::size_t last = std::min<std::size_t>(first + layout.rowsPerBand, std::size_t(px.height));
    const std::size_t stride = layout.rowBytes + 1;
    auto filtered = [&](std::size_t y, std::uint8_t* to) {
      const std::uint8_t* row = px.samples.data() + y * layout.rowBytes;
      filterRow(encoding.filter, layout.bpp, row, y > 0 ? row - layout.rowBytes : nullptr, layout.rowBytes, to);
    };
    deflateReset(&z_);
    const std::size_t from = first - std::min(first, layout.rowsBefore);
    if (from < first) {
      dictionary_.resize((first - from) * stride);
      for (std::size_t y = from; y < first; ++y) filtered(y, dictionary_.data() + (y - from) * stride);
      const std::size_t reach = std::min(dictionary_.size(), kWindowBytes);
      deflateSetDictionary(&z_, dictionary_.data() + dictionary_.size() - reach, static_cast<uInt>(reach));
    }
    row_.resize(stride);
    out.deflated.clear();
    used_ = 0;
    out.adler = adler32(0, nullptr, 0);
    for (std::size_t y = first; y < last; ++y) {
      filtered(y, row_.data());
      out.adler = adler32Update(static_cast<std::uint32_t>(out.adler), row_.data(), stride);
      const bool lastRow = y + 1 == last;
      deflateRow(out.deflated, lastRow ? (last == std::size_t(px.height) ? Z_FINISH : Z_SYNC_FLUSH) : Z_NO_FLUSH);
    }
    out.deflated.resize(used_);
    out.deflated.shrink_to_fit();
    out.filteredBytes = (last - first) * stride;
  }

 private:
  // Deflates row_ onto `to`, whose first used_ bytes are output so far (the
  // rest is room, grown by doubling so each row does not touch the allocator).
  void deflateRow(std::vector<std::uint8_t>& to, int flush) {
    z_.next_in = row_.data();
    z_.avail_in = static_cast<uInt>(row_.size());
    for (;;) {
      if (to.size() - used_ < 4096) to.resize(std::max<std::size_t>(2 * to.size(), 65536));
      z_.next_out = to.data() + used_;
      z_.avail_out = static_cast<uInt>(to.size() - used_);
      const int status = deflate(&z_, flush);
      used_ = to.size() - z_.avail_out;
      if (status == Z_STREAM_END) return;
      if (status != Z_OK && status != Z_BUF_ERROR)
        throw Error(ErrorKind::Internal, fmt::format("PNG encoding: zlib's deflate stopped ({})", status));
      if (z_.avail_in == 0 && z_.avail_out > 0 && flush != Z_FINISH) return;  // all taken, flush complete
    }
  }

  std::size_t used_ = 0;

  z_stream z_{};
  std::vector<std::uint8_t> dictionary_, row_;
};

}  // namespace

std::size_t pngEncoderWorkerBytes(int width, bool indexed) {
  const std::size_t stride = std::size_t(std::max(width, 0)) * (indexed ? 1 : 3) + 1;
  // zlib's deflate state at windowBits 15, memLevel 8 (zlib.h's deflateInit2:
  // (1 << (windowBits + 2)) + (1 << (memLevel + 9)) bytes), the dictionary's
  // rows and one row.
  return (std::size_t(1) << 17) + (std::size_t(1) << 17) + kWindowBytes + 3 * stride;
}

void encodePng(const PngPixels& px, const PngEncoding& encoding, ByteSink& out) {
  const bool indexed = !px.palette.empty();
  Layout layout{};
  layout.bpp = indexed ? 1 : 3;
  layout.rowBytes = std::size_t(px.width) * layout.bpp;
  layout.rowsPerBand = std::max<std::size_t>(1, kPngBandBytes / (layout.rowBytes + 1));
  layout.bands = (std::size_t(px.height) + layout.rowsPerBand - 1) / layout.rowsPerBand;
  layout.rowsBefore = (kDictionaryBytes + layout.rowBytes) / (layout.rowBytes + 1);

  std::vector<Band> bands(layout.bands);
  std::atomic<std::size_t> next{0};
  const unsigned threads = encoding.threads > 0 ? encoding.threads : hardwareThreads();
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(threads, layout.bands));
  runWorkers(
      workers,
      [&](unsigned) {
        BandDeflater deflater(encoding);
        for (std::size_t b; (b = next.fetch_add(1)) < layout.bands;) deflater.run(px, encoding, layout, b, bands[b]);
      },
      [&] { next = layout.bands; });

  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  out.write(kSignature);
  std::vector<std::uint8_t> header;
  appendBigEndian(header, static_cast<std::uint32_t>(px.width));
  appendBigEndian(header, static_cast<std::uint32_t>(px.height));
  header.insert(header.end(), {8, std::uint8_t(indexed ? 3 : 2), 0, 0, 0});  // depth, colour type, methods
  writeChunk(out, "IHDR", header);
  const std::uint8_t perceptual = 0;  // what libpng's simplified API wrote, so viewers show the same
  writeChunk(out, "sRGB", std::span(&perceptual, 1));
  if (indexed) {
    std::vector<std::uint8_t> plte;
    for (const Rgb8& c : px.palette) plte.insert(plte.end(), {c.r, c.g, c.b});
    writeChunk(out, "PLTE", plte);
  }
  // The zlib wrapper (RFC 1950): CMF 0x78 (deflate, 32 KiB window), FLG with
  // the level class and the check bits making CMF * 256 + FLG a multiple of 31.
  const int levelClass = encoding.level <= 1 ? 0 : encoding.level <= 5 ? 1 : encoding.level == 6 ? 2 : 3;
  const unsigned cmfFlg = 0x7800u | unsigned(levelClass << 6);
  const std::uint8_t zlibHeader[2] = {0x78, std::uint8_t((cmfFlg + (31 - cmfFlg % 31) % 31) & 0xff)};
  uLong adler = adler32(0, nullptr, 0);
  for (const Band& band : bands) adler = adler32_combine(adler, band.adler, static_cast<z_off_t>(band.filteredBytes));
  std::vector<std::uint8_t> trailer;
  appendBigEndian(trailer, static_cast<std::uint32_t>(adler));
  for (std::size_t b = 0; b < bands.size(); ++b) {
    writeChunk(out, "IDAT", b == 0 ? std::span<const std::uint8_t>(zlibHeader) : std::span<const std::uint8_t>(),
               bands[b].deflated,
               b + 1 == bands.size() ? std::span<const std::uint8_t>(trailer) : std::span<const std::uint8_t>());
    bands[b].deflated = {};  // written: its memory goes back at once
  }
  writeChunk(out, "IEND", {});
}

std::vector<std::uint8_t> encodePng(const PngPixels& pixels, const PngEncoding& encoding) {
  MemorySink file;
  encodePng(pixels, encoding, file);
  return file.data();
}

}  // namespace lattice::io
