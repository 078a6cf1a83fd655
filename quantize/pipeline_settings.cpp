#include "quantize/pipeline_settings.hpp"

namespace lattice::quantize {

namespace {

using P = PipelineOptions;

// In the order the flags are listed; each help line says why a user would set it.
constexpr Setting<P> kRows[] = {
    whole<&P::maxColors>("colors", {1, 256},
                         "the palette's size: fewer colours, fewer bytes on a slow line (the device may show fewer)"),
    choiceOf<kDitherNames, &P::quantize, &QuantizeOptions::dither>(
        "dither", "fs (Floyd-Steinberg, serpentine) or bayer (ordered 8x8): smoother gradients for more bytes"),
    choiceOf<kSplitRuleNames, &P::quantize, &QuantizeOptions::split>(
        "split", "median (Heckbert 1982) or variance (each cut minimises the squared error): the palette's accuracy"),
    whole<&P::quantize, &QuantizeOptions::refineIterations>(
        "refine", {0, 100}, "k-means iterations after the cut: a closer palette for the time they take"),
    choiceOf<kPipelineModeNames, &P::mode>(
        "mode", "passes (render twice: least memory), frame (keep the 18-bit frame: fastest) or sample (a "
                "subsampled pre-pass for the histogram)"),
    whole<&P::sampleStep>("sample", {1, 16384},
                          "sample mode: the histogram from every Nth row and column; larger is faster, coarser"),
    choiceOf<kHistogramFormNames, &P::quantize, &QuantizeOptions::histogram>(
        "histogram", "full (a counter per 18-bit colour, 1 MiB) or small (the colours present, at most 64 KiB and "
                     "6144 colours: the firmware's form); the same palette either way"),
};

constexpr SettingsSchema<P> kSchema{"quantizer", kRows, [] {
                                      P p;
                                      p.maxColors = 256;
                                      return p;
                                    }};

}  // namespace

const SettingsSchema<PipelineOptions>& pipelineSettings() { return kSchema; }

}  // namespace lattice::quantize
