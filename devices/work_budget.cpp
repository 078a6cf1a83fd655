#include "devices/work_budget.hpp"

#include <fmt/format.h>

#include <vector>

#include "foundation/error.hpp"

namespace lattice {

void checkPixelWork(const DecodeReport& report, const std::string& name) {
  if (!report.overBudget) return;
  throw Error(ErrorKind::Input,
              fmt::format("{}: the stream asks for more drawing than the emulator's budget of {} pixel operations "
                          "(kPixelWorkBudget, docs/limits.md), so it is refused; streams our drivers write stay "
                          "far below it",
                          name, kPixelWorkBudget));
}

void decodeStream(StreamDecoder& decoder, std::FILE* in, const std::string& name) {
  std::vector<std::uint8_t> buffer(1 << 16);
  std::uint64_t total = 0;
  while (true) {
    const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), in);
    total += n;
    if (total > kMaxStreamBytes)
      throw Error(ErrorKind::Input, fmt::format("{}: the stream is longer than the emulator's limit of {} bytes "
                                                "(kMaxStreamBytes, docs/limits.md); an endless input such as "
                                                "/dev/zero stops here",
                                                name, kMaxStreamBytes));
    if (n > 0) decoder.feed(std::span<const std::uint8_t>(buffer.data(), n));
    if (n < buffer.size()) break;
  }
  if (std::ferror(in) != 0) throw Error(ErrorKind::Input, fmt::format("{}: read error", name));
  decoder.finish();
  checkPixelWork(decoder.report(), name);
}

void decodeBytes(StreamDecoder& decoder, std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() > kMaxStreamBytes)
    throw Error(ErrorKind::Input, fmt::format("{}: {} bytes, longer than the emulator's limit of {} bytes", name,
                                              bytes.size(), kMaxStreamBytes));
  decoder.feed(bytes);
  decoder.finish();
  checkPixelWork(decoder.report(), name);
}

}  // namespace lattice
