// Our sixel encoder beside libsixel's, encoder only, in one process: the
// same indexed pixels and palette, encoded into memory by each, alternated.
// Figures in docs/sixel.md ("Encoder only") come from this program:
//
//   sixel_encoder_bench [--runs N] PICTURE.png ...
//
// Method and tunables:
//  * Input: each PNG (bench/sixel-encoder.sh passes Plate 6 median-cut to 16
//    and to 256 colours) is indexed by its own colours (quantize/
//    exact_palette.hpp, what `lattice show` does with it), so both encoders
//    get the same indices and the same palette, and neither quantizes.
//  * Ours: a SixelDriver (devices/sixel/) fed the rows into a reused
//    in-memory sink: header, registers, bands, ST.
//  * libsixel's: sixel_encode (public API, libsixel 1.10.3's sixel.h) of
//    the same pixels as SIXEL_PIXELFORMAT_PAL8, with a sixel_dither made by
//    sixel_dither_new and carrying our palette (sixel_dither_set_palette),
//    written by a sixel_output callback into a reused string. PAL8 pixels
//    are taken as register numbers, with no colour mapping (the decode
//    check below confirms it on every run of this program).
//  * Both build their objects (driver; dither and output) inside the timed
//    run, so each run is one whole in-memory encoding.
//  * Timing: kWarmups untimed runs each, then --runs (default kRuns) pairs,
//    the order swapped every pair so neither always runs on a warm cache;
//    wall time (steady_clock) and this thread's CPU time
//    (CLOCK_THREAD_CPUTIME_ID, which a shared machine's other work does not
//    inflate as it does wall time); medians of the per-run times.
//  * Check: both outputs are decoded by our emulator (SixelDecoder) and by
//    libsixel's sixel_decode_raw; within each decoder the two outputs must
//    give the same colour at every pixel, and our emulator's picture must
//    be the input's colours through the registers' percent rounding.
//    A failed check exits 1.
#include <fmt/format.h>
#include <sixel.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "devices/gun_percent.hpp"
#include "devices/sixel/sixel_decoder.hpp"
#include "devices/sixel/sixel_driver.hpp"
#include "devices/sixel/sixel_forms.hpp"
#include "foundation/error.hpp"
#include "io/png.hpp"
#include "quantize/exact_palette.hpp"

using namespace lattice;

namespace {

constexpr int kRuns = 101;
constexpr int kWarmups = 5;

// A ByteSink that keeps its buffer's capacity from run to run, as the
// string libsixel's callback appends to does.
class ReusedSink final : public ByteSink {
 public:
  using ByteSink::write;
  void write(std::span<const std::uint8_t> bytes) override { data_.insert(data_.end(), bytes.begin(), bytes.end()); }
  std::uint64_t bytesWritten() const override { return data_.size(); }
  void clear() { data_.clear(); }
  const std::vector<std::uint8_t>& data() const { return data_; }

 private:
  std::vector<std::uint8_t> data_;
};

struct Times {
  std::vector<double> wall, cpu;  // seconds a run
};

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

template <typename F>
void timeRun(Times& times, F&& run) {
  const double cpu0 = threadCpuSeconds();
  const auto wall0 = std::chrono::steady_clock::now();
  run();
  const auto wall1 = std::chrono::steady_clock::now();
  const double cpu1 = threadCpuSeconds();
  times.wall.push_back(std::chrono::duration<double>(wall1 - wall0).count());
  times.cpu.push_back(cpu1 - cpu0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

void check(SIXELSTATUS status, const char* what) {
  if (SIXEL_FAILED(status)) throw Error(ErrorKind::Internal, fmt::format("libsixel: {} failed ({:#x})", what, status));
}

int appendToString(char* data, int size, void* priv) {
  static_cast<std::string*>(priv)->append(data, static_cast<std::size_t>(size));
  return size;
}

// libsixel's side: one whole encoding of `pixels` (PAL8) into `out`.
void encodeLibsixel(std::vector<unsigned char>& pixels, std::vector<unsigned char>& palette, const IndexedImage& picture,
                    std::string& out) {
  out.clear();
  sixel_dither_t* dither = nullptr;
  check(sixel_dither_new(&dither, static_cast<int>(picture.colormap.size()), nullptr), "sixel_dither_new");
  sixel_dither_set_palette(dither, palette.data());
  sixel_dither_set_pixelformat(dither, SIXEL_PIXELFORMAT_PAL8);
  sixel_output_t* output = nullptr;
  check(sixel_output_new(&output, appendToString, &out, nullptr), "sixel_output_new");
  const SIXELSTATUS status = sixel_encode(pixels.data(), picture.width, picture.height, 8, dither, output);
  sixel_output_unref(output);
  sixel_dither_unref(dither);
  check(status, "sixel_encode");
}

// Ours: the sixel driver fed the picture's rows.
void encodeOurs(const IndexedImage& picture, ReusedSink& sink) {
  sink.clear();
  sixel::SixelProfile profile;
  profile.registers = 256;
  sixel::SixelDriver driver(sink, profile);
  driver.begin(FrameInfo{picture.width, picture.height, picture.colormap});
  const auto width = static_cast<std::size_t>(picture.width);
  for (int y = 0; y < picture.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(picture.pixels).subspan(std::size_t(y) * width, width));
  driver.end();
}

// Each pixel's colour as our emulator decodes the stream.
std::vector<Rgb8> decodeOurs(std::span<const std::uint8_t> bytes) {
  sixel::SixelProfile profile;
  profile.registers = 256;
  sixel::SixelDecoder decoder(profile);
  decoder.feed(bytes);
  decoder.finish();
  const IndexedImage& image = decoder.image();
  std::vector<Rgb8> colours(image.pixels.size());
  for (std::size_t i = 0; i < colours.size(); ++i) colours[i] = image.colormap.at(image.pixels[i]);
  return colours;
}

// Each pixel's colour as libsixel's sixel_decode_raw decodes the stream.
std::vector<Rgb8> decodeLibsixel(std::span<const std::uint8_t> bytes, int width, int height) {
  std::vector<unsigned char> copy(bytes.begin(), bytes.end());  // the API takes a mutable buffer
  sixel_allocator_t* allocator = nullptr;
  check(sixel_allocator_new(&allocator, nullptr, nullptr, nullptr, nullptr), "sixel_allocator_new");
  unsigned char *pixels = nullptr, *palette = nullptr;
  int w = 0, h = 0, colours = 0;
  const SIXELSTATUS status =
      sixel_decode_raw(copy.data(), static_cast<int>(copy.size()), &pixels, &w, &h, &palette, &colours, allocator);
  std::vector<Rgb8> out;
  if (SIXEL_SUCCEEDED(status) && w == width && h == height) {
    out.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::size_t i = 0; i < out.size(); ++i) {
      const int k = pixels[i];
      out[i] = k < colours ? Rgb8{palette[3 * k], palette[3 * k + 1], palette[3 * k + 2]} : Rgb8{1, 2, 3};
    }
  }
  sixel_allocator_free(allocator, pixels);
  sixel_allocator_free(allocator, palette);
  sixel_allocator_unref(allocator);
  check(status, "sixel_decode_raw");
  return out;
}

std::size_t differing(const std::vector<Rgb8>& a, const std::vector<Rgb8>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] == b[i] ? 0 : 1;
  return n;
}

std::span<const std::uint8_t> bytesOf(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

bool benchOne(const std::string& path, int runs) {
  const RgbImage rgb = io::readPng(path);
  const auto indexed = quantize::exactPalette(rgb, 256);
  if (!indexed) {
    fmt::print(stderr, "{}: more than 256 colours; give it a quantized picture (lattice quantize)\n", path);
    return false;
  }
  const IndexedImage& picture = *indexed;
  std::vector<unsigned char> pixels(picture.pixels.begin(), picture.pixels.end());
  std::vector<unsigned char> palette;
  for (const Rgb8 c : picture.colormap) palette.insert(palette.end(), {c.r, c.g, c.b});

  ReusedSink ours;
  std::string theirs;
  for (int i = 0; i < kWarmups; ++i) {
    encodeOurs(picture, ours);
    encodeLibsixel(pixels, palette, picture, theirs);
  }
  Times oursTimes, theirsTimes;
  for (int i = 0; i < runs; ++i) {
    if (i % 2 == 0) {
      timeRun(oursTimes, [&] { encodeOurs(picture, ours); });
      timeRun(theirsTimes, [&] { encodeLibsixel(pixels, palette, picture, theirs); });
    } else {
      timeRun(theirsTimes, [&] { encodeLibsixel(pixels, palette, picture, theirs); });
      timeRun(oursTimes, [&] { encodeOurs(picture, ours); });
    }
  }

  // The pixels: the input through the registers' percent, as our emulator reads them back.
  std::vector<Rgb8> expected(picture.pixels.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Rgb8 c = picture.colormap[picture.pixels[i]];
    expected[i] = Rgb8{sixel::devices::eightOfPercent(sixel::percentOf(c.r)), sixel::devices::eightOfPercent(sixel::percentOf(c.g)),
                       sixel::devices::eightOfPercent(sixel::percentOf(c.b))};
  }
  const std::vector<Rgb8> oursByOurs = decodeOurs(ours.data()), theirsByOurs = decodeOurs(bytesOf(theirs));
  const std::vector<Rgb8> oursByLib = decodeLibsixel(ours.data(), picture.width, picture.height);
  const std::vector<Rgb8> theirsByLib = decodeLibsixel(bytesOf(theirs), picture.width, picture.height);
  const std::size_t dInput = differing(oursByOurs, expected), dOurDecoder = differing(oursByOurs, theirsByOurs),
                    dLibDecoder = differing(oursByLib, theirsByLib);

  const double ow = median(oursTimes.wall), tw = median(theirsTimes.wall);
  const double oc = median(oursTimes.cpu), tc = median(theirsTimes.cpu);
  fmt::print("{:<6} {:>9} {:>10} {:>6.3f} {:>9.2f} {:>10.2f} {:>6.2f} {:>9.2f} {:>10.2f} {:>6.2f}  {} {} {}  {}\n",
             picture.colormap.size(), ours.data().size(), theirs.size(), double(ours.data().size()) / double(theirs.size()),
             ow * 1e3, tw * 1e3, ow / tw, oc * 1e3, tc * 1e3, oc / tc, dInput, dOurDecoder, dLibDecoder, path);
  return dInput == 0 && dOurDecoder == 0 && dLibDecoder == 0 && !oursByLib.empty();
}

}  // namespace

int main(int argc, char** argv) try {
  int runs = kRuns;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else inputs.push_back(a);
  }
  if (inputs.empty()) {
    fmt::print(stderr, "usage: sixel_encoder_bench [--runs N] PICTURE.png ...  (quantized pictures; "
                       "bench/sixel-encoder.sh makes Plate 6's)\n");
    return 2;
  }
  fmt::print("{} runs each, alternated; medians of per-run times in ms (wall, and this thread's CPU)\n", runs);
  fmt::print("{:<6} {:>9} {:>10} {:>6} {:>9} {:>10} {:>6} {:>9} {:>10} {:>6}  {}\n", "colors", "ours B", "libsixel B",
             "ratio", "ours ms", "libsixel", "ratio", "ours cpu", "lib cpu", "ratio",
             "pixels differing: ours vs input, ours vs libsixel's by our decoder, by libsixel's decoder");
  bool ok = true;
  for (const std::string& path : inputs) ok = benchOne(path, runs) && ok;
  if (!ok) fmt::print(stderr, "sixel_encoder_bench: the decoded pixels differ (see the columns above)\n");
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  fmt::print(stderr, "sixel_encoder_bench: {}\n", e.what());
  return 1;
}
