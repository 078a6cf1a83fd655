#include "io/stream_sender.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "foundation/error.hpp"

namespace lattice::io {
namespace {

// Small enough that progress moves often at 9600 baud (~1 s per KB), large
// enough that a fast line is not held up by per-chunk work.
constexpr std::size_t kChunk = 512;

std::string shellQuote(const std::string& text) {
  bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' || c == '.' ||
           c == '_' || c == '-' || c == '+' || c == ',' || c == ':' || c == '=' || c == '@';
  });
  if (plain) return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

SendResult sendStream(std::span<const std::uint8_t> stream, std::uint64_t resumeOffset, SerialSink& sink,
                      const SendProgress& progress) {
  if (resumeOffset > stream.size())
    throw Error(ErrorKind::Usage, fmt::format("--resume {}: past the end of the stream ({} bytes); use an offset "
                                              "from 0 to {}, as printed by the failed send",
                                              resumeOffset, stream.size(), stream.size()));
  auto start = std::chrono::steady_clock::now();
  sink.setStreamOffset(resumeOffset);
  auto rest = stream.subspan(static_cast<std::size_t>(resumeOffset));
  std::uint64_t offset = resumeOffset;
  while (!rest.empty()) {
    auto chunk = rest.first(std::min(kChunk, rest.size()));
    sink.write(chunk);
    offset += chunk.size();
    rest = rest.subspan(chunk.size());
    if (progress) progress(offset);
  }
  sink.close();
  return {offset - resumeOffset, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

std::string resumeCommand(const std::string& file, const SerialOptions& options, std::uint64_t offset) {
  SerialOptions quoted = options;
  quoted.port = shellQuote(options.port);
  return fmt::format("lattice send {} {} --resume {}", shellQuote(file), serialFlags(quoted), offset);
}

}  // namespace lattice::io
