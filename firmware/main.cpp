// The firmware's job: the baked scene (firmware/baked_scene.hpp) rendered in
// Q31.32 fixed point (Renderer<Fixed32>, no floating point on the per-pixel
// path), quantized with the small histogram, and written by the Tek 4125
// driver to UART0 - the same calls `lattice render --arith fixed --device
// tek4125` makes on the host, so the stream is the same byte for byte.
// Then a report on the host's stderr (semihosting; never on the UART):
// picture, stream bytes, palette, and the RAM high-water marks against the
// budget. Exit status: 0, or a lattice::Error's kind (docs/cli.md), or 3
// when the heap runs out.
#include <fmt/format.h>

#include <malloc.h>
#include <new>

#include "devices/tek4125/tek4125_driver.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "firmware/baked_scene.hpp"
#include "firmware/firmware_main.hpp"
#include "firmware/memory_marks.hpp"
#include "firmware/semihosting.hpp"
#include "firmware/uart_sink.hpp"
#include "firmware/virtual_clock.hpp"
#include "foundation/error.hpp"
#include "foundation/fixed.hpp"
#include "render/renderer.hpp"

namespace lattice::firmware {
namespace {

int run() {
  startClock();
  const BakedScene baked = bakedScene();
  RenderSettings settings;
  settings.width = baked.width;
  settings.height = baked.height;
  settings.threads = 1;
  Renderer<Fixed32> renderer(baked.scene, settings);
  // What the scene costs in RAM once built (newlib's bytes in use): the
  // baked tree's nodes and the renderer's few primitives; the instances and
  // tables are read from flash (docs/firmware.md).
  const std::size_t sceneHeap = static_cast<std::size_t>(mallinfo().uordblks);
  tek4125::Tek4125Profile profile;
  tek4125::applyOverrides(profile, baked.settings);
  UartSink uart;
  tek4125::Tek4125Driver driver(uart, profile);
  const quantize::PipelineReport report = quantize::runPipeline(renderer, driver, baked.pipeline);
  uart.close();
  const std::uint64_t ticks = clockTicks();
  const MemoryMarks m = memoryMarks();
  hostReport(fmt::format("firmware: {} {}x{} fixed-point on {}, {} stream bytes on its UART, {} colours of {} distinct, "
                         "{} rays\n",
                         baked.name, baked.width, baked.height, LATTICE_BOARD_NAME, uart.bytesWritten(), report.paletteSize,
                         report.distinctColors, renderer.raysTraced()));
  hostReport(fmt::format("firmware: RAM peak {} B of {} (data {} + bss {} + heap {} of {} + stack {} of {}); "
                         "the scene set up holds {} B of heap\n",
                         m.total(), LATTICE_BOARD_BUDGET, m.data, m.bss, m.heapPeak, m.heapLimit, m.stackPeak,
                         m.stackSize, sceneHeap));
  if (m.stackPeak >= m.stackSize) {
    // The painted stack is used up to its limit: it may have run into the heap.
    hostReport(fmt::format("firmware: the stack reached its limit ({} B): it may have overflowed\n", m.stackSize));
    return static_cast<int>(ErrorKind::Internal);
  }
  // Under `qemu -icount shift=0` this is the instruction count (firmware/virtual_clock.hpp).
  hostReport(fmt::format("firmware: virtual time {} ns ({} SysTick ticks at {} Hz)\n", tickNanoseconds(ticks),
                         ticks, kClockHz));
  return 0;
}

}  // namespace
}  // namespace lattice::firmware

int lattice::firmware::firmwareMain() {
  try {
    return run();
  } catch (const lattice::Error& e) {
    hostReport(fmt::format("firmware: error: {}\n", e.what()));
    return static_cast<int>(e.kind());
  } catch (const std::bad_alloc&) {
    const MemoryMarks m = memoryMarks();
    hostReport(fmt::format("firmware: out of memory: the heap's {} B are used up (docs/firmware.md)\n", m.heapLimit));
    return static_cast<int>(lattice::ErrorKind::Input);  // as the host exits on bad_alloc (docs/cli.md)
  }
}
