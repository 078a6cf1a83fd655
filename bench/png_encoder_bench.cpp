// PNG encoders side by side on one truecolour picture, in memory: how the
// encoder io/png.cpp writes with (io/png_encoder.hpp) was chosen. Figures in
// docs/architecture.md ("How the work is split") come from bench/png-encoder.sh,
// which runs this program:
//
//   png_encoder_bench [--runs N] PICTURE.png
//
// Method:
//  * Contenders: libpng's simplified API as io/png.cpp called it before
//    (png_image_write_to_memory once for the size, once to write); libpng's
//    own writer in one pass at its defaults (level 6, adaptive filters) and
//    at level 1 with the Up filter; libspng 0.7.3 (Debian's libspng-dev) at
//    its defaults and at level 1 with Up; ours at zlib levels 1 and 6, with
//    and without Z_RLE, under each fixed filter, on 1 thread, and the chosen
//    setting on 2.
//  * Timing: one untimed run of each, then --runs rounds, each running every
//    contender once in turn (the order rotated every round so none is
//    always first); wall time (steady_clock) and the process's CPU time
//    (every thread's); medians.
//  * Check: every output is decoded by io::readPngBytes (libpng) and must
//    hold the input's pixels exactly; a failure exits 1.
#include <fmt/format.h>
#include <png.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "foundation/error.hpp"
#include "io/png.hpp"
#include "io/png_encoder.hpp"
#if LATTICE_BENCH_SPNG
#include <spng.h>
#endif

namespace {

using Bytes = std::vector<std::uint8_t>;
using lattice::RgbImage;

Bytes libpngSimplified(const RgbImage& img) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(img.width);
  image.height = png_uint_32(img.height);
  image.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  png_image_write_to_memory(&image, nullptr, &size, 0, img.rgb.data(), 0, nullptr);
  Bytes out(size);
  png_image_write_to_memory(&image, out.data(), &size, 0, img.rgb.data(), 0, nullptr);
  out.resize(size);
  return out;
}

// libpng's own writer, one pass; level < 0 and filters 0 keep its defaults.
Bytes libpngOnePass(const RgbImage& img, int level, int filters) {
  Bytes out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw lattice::Error(lattice::ErrorKind::Internal, "libpng failed");
  }
  png_set_write_fn(
      png, &out,
      [](png_structp p, png_bytep data, png_size_t n) {
        auto* o = static_cast<Bytes*>(png_get_io_ptr(p));
        o->insert(o->end(), data, data + n);
      },
      nullptr);
  if (level >= 0) png_set_compression_level(png, level);
  if (filters != 0) png_set_filter(png, 0, filters);
  png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < img.height; ++y) png_write_row(png, img.pixel(0, y));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

#if LATTICE_BENCH_SPNG
// libspng; level < 0 and filters 0 keep its defaults.
Bytes libspng(const RgbImage& img, int level, int filters) {
  spng_ctx* ctx = spng_ctx_new(SPNG_CTX_ENCODER);
  spng_set_option(ctx, SPNG_ENCODE_TO_BUFFER, 1);
  if (level >= 0) spng_set_option(ctx, SPNG_IMG_COMPRESSION_LEVEL, level);
  if (filters != 0) spng_set_option(ctx, SPNG_FILTER_CHOICE, filters);
  spng_ihdr ihdr{};
  ihdr.width = std::uint32_t(img.width);
  ihdr.height = std::uint32_t(img.height);
  ihdr.bit_depth = 8;
  ihdr.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
  spng_set_ihdr(ctx, &ihdr);
  int status = spng_encode_image(ctx, img.rgb.data(), img.rgb.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE);
  std::size_t size = 0;
  void* buffer = status == 0 ? spng_get_png_buffer(ctx, &size, &status) : nullptr;
  spng_ctx_free(ctx);
  if (!buffer) throw lattice::Error(lattice::ErrorKind::Internal, fmt::format("libspng failed: {}", spng_strerror(status)));
  Bytes out(static_cast<std::uint8_t*>(buffer), static_cast<std::uint8_t*>(buffer) + size);
  std::free(buffer);
  return out;
}
#endif

Bytes ours(const RgbImage& img, int level, bool rle, lattice::io::PngFilter filter, unsigned threads) {
  lattice::io::PngPixels px{img.width, img.height, img.rgb, {}};
  return lattice::io::encodePng(px, {level, rle, filter, threads});
}

struct Contender {
  Contender(std::string n, std::function<Bytes()> e) : name(std::move(n)), encode(std::move(e)) {}
  std::string name;
  std::function<Bytes()> encode;
  std::vector<double> wall, cpu;
  std::size_t bytes = 0;
};

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) try {
  int runs = 7;
  std::string picture;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else picture = argv[i];
  }
  if (picture.empty()) {
    std::fprintf(stderr, "usage: png_encoder_bench [--runs N] PICTURE.png\n");
    return 2;
  }
  const RgbImage img = lattice::io::readPng(picture);
  using lattice::io::PngFilter;
  std::vector<Contender> all;
  all.push_back({"libpng simplified API, twice (before)", [&] { return libpngSimplified(img); }});
  all.push_back({"libpng one pass, level 6, adaptive", [&] { return libpngOnePass(img, -1, 0); }});
  all.push_back({"libpng one pass, level 1, Up", [&] { return libpngOnePass(img, 1, PNG_FILTER_UP); }});
#if LATTICE_BENCH_SPNG
  all.push_back({"libspng defaults", [&] { return libspng(img, -1, 0); }});
  all.push_back({"libspng level 1, Up", [&] { return libspng(img, 1, SPNG_FILTER_CHOICE_UP); }});
#endif
  const std::pair<const char*, PngFilter> filters[] = {
      {"None", PngFilter::None}, {"Sub", PngFilter::Sub}, {"Up", PngFilter::Up}, {"Paeth", PngFilter::Paeth}};
  for (int level : {1, 6})
    for (bool rle : {true, false})
      for (auto [name, filter] : filters)
        all.push_back({fmt::format("ours level {}{}, {}, 1 thread", level, rle ? " RLE" : "", name),
                       [&img, level, rle, filter = filter] { return ours(img, level, rle, filter, 1); }});
  const lattice::io::PngEncoding chosen;
  const char* chosenFilter = "";
  for (auto [name, filter] : filters)
    if (filter == chosen.filter) chosenFilter = name;
  all.push_back({fmt::format("ours as written (level {}{}, {}), 2 threads", chosen.level, chosen.runLength ? " RLE" : "",
                             chosenFilter),
                 [&] { return ours(img, chosen.level, chosen.runLength, chosen.filter, 2); }});

  for (Contender& c : all) {  // the untimed run, and the pixel check
    const Bytes out = c.encode();
    c.bytes = out.size();
    if (lattice::io::readPngBytes(out, c.name).rgb != img.rgb) {
      std::fprintf(stderr, "png_encoder_bench: %s does not decode to the input's pixels\n", c.name.c_str());
      return 1;
    }
  }
  for (int r = 0; r < runs; ++r)
    for (std::size_t i = 0; i < all.size(); ++i) {
      Contender& c = all[(i + std::size_t(r)) % all.size()];
      const double cpu0 = cpuSeconds();
      const auto t0 = std::chrono::steady_clock::now();
      const Bytes out = c.encode();
      c.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      c.cpu.push_back(cpuSeconds() - cpu0);
    }
  fmt::print("{}: {}x{}, {} rounds\n", picture, img.width, img.height, runs);
  fmt::print("| encoder | wall ms (median) | CPU ms (median) | bytes | of raw |\n|---|---:|---:|---:|---:|\n");
  for (const Contender& c : all)
    fmt::print("| {} | {:.1f} | {:.1f} | {} | {:.1f} % |\n", c.name, median(c.wall) * 1e3, median(c.cpu) * 1e3, c.bytes,
               100.0 * double(c.bytes) / double(img.rgb.size()));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "png_encoder_bench: %s\n", e.what());
  return 1;
}
