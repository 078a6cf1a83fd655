// The device path gives the same stream for any thread count: renderScene
// (app/render_job.hpp) to the Tek 4125 with 1, 2, 3 and 8 threads, where the
// renderer's pool renders the next band of rows while the quantizer reads
// this one (render/renderer.cpp), and a kept frame (--mode frame) is counted
// and mapped over bands on every thread (quantize/frame_bands.hpp: 67 rows
// give two bands of histogram, three of mapping). Every quantizer mode reads the rows in
// its own order (passes: twice from the top; sample: every Nth row first),
// on a plain scene, a lattice scene and a scatter traced in full (instance
// nodes), in double and float. The PNG of the emulated screen is compared
// too, and a truecolour PNG (io/png_encoder.hpp deflates its bands on every
// thread) must be the same file whatever the count.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <string>

#include "app/render_job.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Output {
  std::string stream, picture;
};

Output renderWith(const app::RenderJob& base, int threads, const testing::TempDir& dir) {
  app::RenderJob job = base;
  job.render.threads = threads;
  job.output.stream = dir / fmt::format("t{}.tek", threads);
  job.output.picture = dir / fmt::format("t{}.png", threads);
  job.quiet = true;
  app::renderScene(job);
  return {slurp(job.output.stream), slurp(job.output.picture)};
}

}  // namespace

TEST_CASE("render threads: the device stream is the same for 1, 2, 3 and 8 threads in every quantizer mode") {
  testing::TempDir dir("render-threads");
  struct Case {
    const char* scene;
    bool full;
    const char* arithmetic;
  };
  for (const Case& c : {Case{"sphere-hole.toml", false, "double"}, Case{"hook.toml", false, "float"},
                        Case{"fuzzy-sphere-1000.toml", true, "double"}, Case{"fuzzy-sphere-1000.toml", true, "float"}}) {
    for (const auto mode : {quantize::PipelineMode::TwoPass, quantize::PipelineMode::Frame,
                            quantize::PipelineMode::Sample}) {
      INFO(c.scene << (c.full ? " --full " : " ") << c.arithmetic << ", mode " << quantize::pipelineModeName(mode));
      app::RenderJob job;
      job.scene = testing::sourcePath(fmt::format("scenes/{}", c.scene)).string();
      job.output.device = "tek4125";
      job.render.width = 72;
      job.render.height = 67;  // not a multiple of any band
      job.arithmetic = c.arithmetic;
      job.render.build.fullRayTrace = c.full;
      job.pipeline.mode = mode;
      const Output one = renderWith(job, 1, dir);
      REQUIRE(one.stream.size() > 1000);
      for (int threads : {2, 3, 8}) {
        INFO(threads << " threads");
        const Output many = renderWith(job, threads, dir);
        CHECK(many.stream == one.stream);
        CHECK(many.picture == one.picture);
      }
    }
  }
}

TEST_CASE("render threads: a truecolour PNG is the same file for 1 to 4 threads, and its phases are timed") {
  testing::TempDir dir("render-threads-png");
  app::RenderJob job;
  job.scene = testing::sourcePath("scenes/sphere-hole.toml").string();
  job.render.width = 300;
  job.render.height = 701;  // 900 bytes a row: three bands of the PNG encoder, the last one short
  job.quiet = true;
  std::string first;
  for (int threads : {1, 2, 3, 4}) {
    INFO(threads << " threads");
    job.render.threads = threads;
    job.output.picture = dir / fmt::format("t{}.png", threads);
    const app::RenderResult r = app::renderScene(job);
    CHECK(r.phases.setup.wall > 0);
    CHECK(r.phases.trace.wall > 0);
    CHECK(r.phases.trace.cpu > 0);
    CHECK(r.phases.quantize.wall == 0);  // no quantizer on the truecolour path
    CHECK(r.phases.output.wall > 0);
    CHECK(r.phases.setup.wall + r.phases.trace.wall + r.phases.output.wall <= r.seconds);
    const std::string picture = slurp(job.output.picture);
    if (first.empty()) first = picture;
    CHECK(picture == first);
  }
  REQUIRE(first.size() > 1000);
}
