#include "app/stream_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <string_view>

#include "devices/device_table.hpp"
#include "devices/stream_shape.hpp"
#include "foundation/error.hpp"

namespace lattice::app {
namespace {

bool startsWith(std::span<const std::uint8_t> head, std::string_view magic) {
  return head.size() >= magic.size() && std::memcmp(head.data(), magic.data(), magic.size()) == 0;
}

bool contains(std::span<const std::uint8_t> head, std::string_view text) {
  const std::string_view all(reinterpret_cast<const char*>(head.data()), head.size());
  return all.find(text) != std::string_view::npos;
}

// Text: no control characters besides tab, CR, LF and form feed.
bool isText(std::span<const std::uint8_t> head) {
  return std::none_of(head.begin(), head.end(), [](std::uint8_t b) {
    return b == 0x7F || (b < 0x20 && b != '\t' && b != '\n' && b != '\r' && b != '\f');
  });
}

}  // namespace

std::string describeContent(std::span<const std::uint8_t> head) {
  if (head.empty()) return "an empty file";
  if (startsWith(head, "\x89PNG\r\n\x1a\n")) return "a PNG image";
  if (startsWith(head, "\xff\xd8\xff")) return "a JPEG image";
  if (startsWith(head, "GIF8")) return "a GIF image";
  if (startsWith(head, "\x1f\x8b")) return "a gzip-compressed file";
  if (startsWith(head, "PK\x03\x04")) return "a zip archive";
  if (startsWith(head, "LATLHT\r\n")) return "a lattice hash table (.lht)";
  if (startsWith(head, "\x7f" "ELF")) return "a program (ELF)";
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    const devices::Device device = entry.make({});
    if (device.recognise && device.recognise(head)) return fmt::format("a {} stream", device.title);
  }
  if (isText(head)) {
    if (contains(head, "[[objects]]") || contains(head, "[camera]") || contains(head, "[[lights]]") ||
        contains(head, "[options]") || contains(head, "[[lattices]]"))
      return "a scene file (TOML)";
    return "text";
  }
  return "binary data";
}

CheckedDecoder::CheckedDecoder(std::unique_ptr<StreamDecoder> inner, const devices::Device& device, std::string name)
    : inner_(std::move(inner)), device_(device), name_(std::move(name)) {}

void CheckedDecoder::feed(std::span<const std::uint8_t> bytes) {
  if (checked_) return inner_->feed(bytes);
  const std::size_t take = std::min(bytes.size(), devices::kRecogniseBytes - head_.size());
  head_.insert(head_.end(), bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(take));
  if (head_.size() < devices::kRecogniseBytes) return;
  check();
  inner_->feed(head_);
  inner_->feed(bytes.subspan(take));
}

void CheckedDecoder::finish() {
  if (!checked_) {
    check();
    inner_->feed(head_);
  }
  inner_->finish();
}

void CheckedDecoder::check() {
  checked_ = true;
  if (!device_.recognise) return;
  if (!head_.empty() && device_.recognise(head_)) return;
  const std::string looks = describeContent(head_);
  std::string fix;
  if (head_.empty()) {
    fix = "render a stream first, e.g. lattice render SCENE.toml --device " + device_.name + " --stream OUT";
  } else if (looks.rfind("a scene file", 0) == 0) {
    fix = fmt::format("render it to a stream first: lattice render {} --device {} --stream OUT", name_, device_.name);
  } else if (looks.size() > 7 && looks.compare(looks.size() - 7, 7, " stream") == 0) {
    for (const devices::DeviceEntry& entry : devices::deviceTable()) {
      const devices::Device other = entry.make({});
      if (other.recognise && other.recognise(head_)) {
        fix = fmt::format("emulate it with --device {}", other.name);
        break;  // the table's first device that takes it: the 4125 reads 4014 forms too, not the reverse
      }
    }
  } else {
    fix = fmt::format("give a {} command stream", device_.title);
  }
  throw Error(ErrorKind::Input, fmt::format("{}: this is {}, not a {} stream; {} (--raw decodes the bytes anyway)",
                                            name_, looks, device_.title, fix));
}

}  // namespace lattice::app
