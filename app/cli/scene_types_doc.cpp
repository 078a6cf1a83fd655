#include "app/cli/scene_types_doc.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "foundation/error.hpp"
#include "loader/lattice_scene_loader.hpp"

namespace lattice::app {
namespace {

constexpr std::string_view kProbeKey = "zz_probe_key";

// The list after "expected one of: " in the loader's message for `text`.
std::vector<std::string> expectedNames(const std::string& text) {
  try {
    (void)lht::parseSceneWithLattices(text, "probe.toml");
  } catch (const Error& e) {
    const std::string message = e.what();
    const std::string marker = "expected one of: ";
    const std::size_t at = message.find(marker);
    if (at == std::string::npos) throw Error(ErrorKind::Internal, "scene-type probe: unexpected message: " + message);
    std::vector<std::string> names;
    std::string rest = message.substr(at + marker.size());
    for (std::size_t start = 0; start <= rest.size();) {
      const std::size_t comma = rest.find(", ", start);
      names.push_back(rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 2;
    }
    return names;
  }
  throw Error(ErrorKind::Internal, "scene-type probe: the loader accepted an unknown name");
}

}  // namespace

NodeTypeTable nodeTypeTable() {
  NodeTypeTable table;
  const std::vector<std::string> types =
      expectedNames(fmt::format("[[objects]]\ntype = \"{}\"\n", kProbeKey));
  std::vector<std::vector<std::string>> keysOf;
  for (const std::string& type : types)
    keysOf.push_back(expectedNames(fmt::format("[[objects]]\ntype = \"{}\"\n{} = 1\n", type, kProbeKey)));
  // Common: in every type's list.
  for (const std::string& key : keysOf.front())
    if (std::all_of(keysOf.begin(), keysOf.end(),
                    [&](const std::vector<std::string>& keys) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }))
      table.common.push_back(key);
  for (std::size_t i = 0; i < types.size(); ++i) {
    NodeTypeKeys entry{types[i], {}};
    for (const std::string& key : keysOf[i])
      if (std::find(table.common.begin(), table.common.end(), key) == table.common.end()) entry.keys.push_back(key);
    table.types.push_back(std::move(entry));
  }
  return table;
}

std::string nodeTypeMarkdown(const NodeTypeTable& table) {
  const auto code = [](const std::vector<std::string>& names) {
    std::vector<std::string> quoted;
    for (const std::string& n : names) quoted.push_back("`" + n + "`");
    return quoted.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(quoted, ", "));
  };
  std::string text = "| type | its own keys |\n|---|---|\n";
  for (const NodeTypeKeys& entry : table.types) text += fmt::format("| `{}` | {} |\n", entry.type, code(entry.keys));
  text += fmt::format("\nEvery type also takes {}.\n", code(table.common));
  return text;
}

}  // namespace lattice::app
