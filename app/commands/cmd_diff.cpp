// `lattice diff A.png B.png [-o DIFF.png] [--block N]`: how far two renders
// are apart. Used to compare a lattice render with the full ray trace of the
// same scene (`lattice render --full`), the comparison thesis ch. 4 leaves
// to the reader's eye (docs/gallery.md).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>

#include "app/commands/commands.hpp"
#include "app/cli/number_flags.hpp"
#include "io/image_metrics.hpp"
#include "io/png.hpp"
#include "foundation/error.hpp"

namespace {

struct DiffOptions {
  std::string a;
  std::string b;
  std::string output;
  int block = 8;
  double gain = 8.0;
};

void runDiff(const DiffOptions& o) {
  if (o.block < 1)
    throw lattice::Error(lattice::ErrorKind::Usage, fmt::format("--block {}: use a block size of 1 or more pixels", o.block));
  if (!(o.gain > 0) || !std::isfinite(o.gain))
    throw lattice::Error(lattice::ErrorKind::Usage, fmt::format("--gain {}: use a positive gain, e.g. --gain 8", o.gain));
  const lattice::io::ImagePair images = lattice::io::readComparablePngs(o.a, o.b);
  const lattice::io::ImageMetrics m = lattice::io::compareRgb(images.a, images.b, o.block);
  const double pixels = double(m.width) * double(m.height);
  const auto line = [](const std::string& label, const std::string& value) { fmt::print("{:<16}{}\n", label, value); };
  line("images", fmt::format("{} vs {} ({}x{})", o.a, o.b, m.width, m.height));
  line("PSNR", std::isinf(m.psnr) ? std::string("inf (identical)") : fmt::format("{:.2f} dB", m.psnr));
  line("RMS", fmt::format("{:.3f} (of 255)", m.rms));
  line("max error", fmt::format("{} (of 255, one channel)", m.maxChannelError));
  line("differing", fmt::format("{} pixels ({:.2f}%)", m.differingPixels,
                                pixels > 0 ? 100.0 * double(m.differingPixels) / pixels : 0.0));
  line(fmt::format("{}x{} blocks", m.blockSize, m.blockSize),
       fmt::format("worst mean |diff| {:.2f} at ({}, {}), mean {:.3f}", m.worstBlockMean, m.worstBlockX,
                   m.worstBlockY, m.meanBlockMean));
  if (!o.output.empty()) {
    lattice::io::writePng(o.output, lattice::io::amplifiedDifference(images.a, images.b, o.gain));
    line("difference", fmt::format("{} (|A - B| x {:g})", o.output, o.gain));
  }
}

}  // namespace

namespace lattice::app {

void addDiff(CLI::App& root) {
  auto o = std::make_shared<DiffOptions>();
  auto* cmd = root.add_subcommand(
      "diff",
      "Compare two PNGs of the same size: PSNR, RMS and largest channel error, how many pixels differ,\n"
      "and the worst and mean N x N block of mean absolute difference; optionally write |A - B|, amplified");
  cmd->add_option("a", o->a, "First PNG (e.g. the lattice render)")->required();
  cmd->add_option("b", o->b, "Second PNG (e.g. the --full render)")->required();
  cmd->add_option("-o,--output", o->output, "Write the amplified difference image here (PNG, atomically)");
  cmd->add_option("--block", o->block, "Block size N for the worst/mean block figure (default 8)")
      ->check(lattice::app::numberIn({1, 16384, true}));
  cmd->add_option("--gain", o->gain, "Multiply |A - B| by this in the difference image (default 8)")
      ->check(lattice::app::numberIn({0, 1e6}));
  cmd->footer(
      "Errors are per channel on the 0..255 scale; PSNR is against a peak of 255. A block's figure is the\n"
      "mean |A - B| over its pixels and channels, so one bad region shows even when the whole-image RMS is small.\n"
      "Example:\n"
      "  lattice render scenes/fuzzy-sphere-1000.toml -o lattice.png\n"
      "  lattice render scenes/fuzzy-sphere-1000.toml --full -o full.png\n"
      "  lattice diff lattice.png full.png -o diff.png --block 8");
  cmd->callback([o] { runDiff(*o); });
}

}  // namespace lattice::app
