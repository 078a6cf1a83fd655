#include "app/stream_check.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
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

// A file format told by its magic number, which no device's stream starts
// with; nullptr if none. Asked before the recognisers: bytes that happen to
// pass one inside a PNG do not make it a stream.
const char* fileFormat(std::span<const std::uint8_t> head) {
  if (startsWith(head, "\x89PNG\r\n\x1a\n")) return "a PNG image";
  if (startsWith(head, "\xff\xd8\xff")) return "a JPEG image";
  if (startsWith(head, "GIF8")) return "a GIF image";
  if (startsWith(head, "\x1f\x8b")) return "a gzip-compressed file";
  if (startsWith(head, "PK\x03\x04")) return "a zip archive";
  if (startsWith(head, "LATLHT\r\n")) return "a lattice hash table (.lht)";
  if (startsWith(head, "\x7f" "ELF")) return "a program (ELF)";
  return nullptr;
}

// Recognisers overlap where one terminal reads another's language: the 4125
// reads the 4010/4014 graphics (GS vectors, FS points), so a 4014 stream
// passes the 4125's recogniser as well as its own, while the 4014's refuses
// any 4100-series command. A device listed here answers only when no other
// device takes the bytes.
constexpr std::string_view kReadsOthers[] = {"tek4125"};

bool readsOthers(std::string_view name) {
  return std::find(std::begin(kReadsOthers), std::end(kReadsOthers), name) != std::end(kReadsOthers);
}

bool isScene(const std::string& looks) { return looks.rfind("a scene file", 0) == 0; }

// What --raw does, for the end of a refusal.
std::string_view rawDoes(StreamUse use) {
  switch (use) {
    case StreamUse::Emulate: return "--raw decodes the bytes anyway";
    case StreamUse::Send:
    case StreamUse::SendVirtual: return "--raw sends the bytes anyway";
    case StreamUse::Show: return "--raw shows what the emulator makes of them anyway";
  }
  return "--raw skips this check";
}

// How the command is told that the stream is `device`'s.
std::string useDevice(StreamUse use, std::string_view device) {
  switch (use) {
    case StreamUse::Emulate: return fmt::format("emulate it with --device {}", device);
    case StreamUse::Send: return fmt::format("send it with --device {}, or without --device", device);
    case StreamUse::SendVirtual: return fmt::format("send it to --port virtual:{}", device);
    case StreamUse::Show: return fmt::format("show it with --as {}, or without --as", device);
  }
  return std::string(device);
}

}  // namespace

std::string describeContent(std::span<const std::uint8_t> head) {
  if (head.empty()) return "an empty file";
  if (const char* format = fileFormat(head)) return format;
  if (const std::string device = recogniseDevice(head); !device.empty())
    return fmt::format("a {} stream", devices::makeDevice(device).title);
  if (isText(head)) {
    if (contains(head, "[[objects]]") || contains(head, "[camera]") || contains(head, "[[lights]]") ||
        contains(head, "[options]") || contains(head, "[[lattices]]"))
      return "a scene file (TOML)";
    return "text";
  }
  return "binary data";
}

std::string recogniseDevice(std::span<const std::uint8_t> head) {
  if (head.empty() || fileFormat(head) != nullptr) return {};
  std::string broad;  // a device that reads others' streams and takes this one
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    const devices::Device device = entry.make({});
    if (!device.recognise || !device.recognise(head)) continue;
    if (!readsOthers(entry.name)) return std::string(entry.name);
    if (broad.empty()) broad = entry.name;
  }
  return broad;
}

std::vector<std::uint8_t> readStreamHead(const std::string& path) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (in == nullptr) throw Error(ErrorKind::Input, fmt::format("{}: cannot open: {}", path, std::strerror(errno)));
  std::vector<std::uint8_t> head(devices::kRecogniseBytes);
  const std::size_t got = std::fread(head.data(), 1, head.size(), in);
  const int error = std::ferror(in) ? errno : 0;
  std::fclose(in);
  if (error != 0) throw Error(ErrorKind::Input, fmt::format("{}: cannot read: {}", path, std::strerror(error)));
  head.resize(got);
  return head;
}

void requireStream(std::span<const std::uint8_t> head, const devices::Device& device, const std::string& name,
                   StreamUse use) {
  if (!device.recognise) return;
  if (!head.empty() && fileFormat(head) == nullptr && device.recognise(head)) return;
  const std::string looks = describeContent(head);
  const std::string other = recogniseDevice(head);
  std::string fix;
  if (head.empty()) {
    fix = "render a stream first, e.g. lattice render SCENE.toml --device " + device.name + " --stream OUT";
  } else if (isScene(looks)) {
    fix = fmt::format("render it to a stream first: lattice render {} --device {} --stream OUT", name, device.name);
  } else if (!other.empty()) {
    fix = useDevice(use, other);
  } else if (use == StreamUse::Show && looks == "a PNG image") {
    fix = "show it without --as";
  } else {
    fix = fmt::format("give a {} command stream", device.title);
  }
  throw Error(ErrorKind::Input, fmt::format("{}: this is {}, not a {} stream; {} ({})", name, looks, device.title,
                                            fix, rawDoes(use)));
}

void requireAnyStream(std::span<const std::uint8_t> head, const std::string& name, StreamUse use) {
  if (!recogniseDevice(head).empty()) return;
  const std::string looks = describeContent(head);
  const std::string what = fmt::format("{}: this is {}, not a stream of any device lattice knows ({})", name, looks,
                                       fmt::join(devices::deviceNames(), ", "));
  std::string fix;
  if (head.empty()) fix = "render a stream first, e.g. lattice render SCENE.toml --device DEVICE --stream OUT";
  else if (isScene(looks))
    fix = fmt::format("render it to a stream first: lattice render {} --device DEVICE --stream OUT", name);
  else if (use != StreamUse::Show) fix = "give a terminal's command stream, such as lattice render --stream writes";
  // show decodes with one device's emulator, so forcing it names the device.
  const std::string force = use == StreamUse::Show ? "--as DEVICE --raw shows what that device's emulator makes of it"
                                                   : std::string(rawDoes(use));
  throw Error(ErrorKind::Input, fix.empty() ? fmt::format("{}; {}", what, force)
                                            : fmt::format("{}; {} ({})", what, fix, force));
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
  requireStream(head_, device_, name_, StreamUse::Emulate);
}

}  // namespace lattice::app
