#include "loader/canonical_toml.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

namespace lattice::lht {
namespace {

void appendSized(std::string& out, std::string_view text) {
  out += std::to_string(text.size());
  out += ':';
  out += text;
}

void appendDate(std::string& out, const toml::date& d) { out += fmt::format("D{}-{}-{}", d.year, d.month, d.day); }
void appendTime(std::string& out, const toml::time& t) {
  out += fmt::format("T{}:{}:{}.{}", t.hour, t.minute, t.second, t.nanosecond);
}

void append(std::string& out, const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: {
      const toml::table& table = *node.as_table();
      std::vector<std::pair<std::string_view, const toml::node*>> entries;
      for (auto&& [key, value] : table) entries.emplace_back(key.str(), &value);
      std::sort(entries.begin(), entries.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      out += '{';
      for (const auto& [key, value] : entries) {
        appendSized(out, key);
        out += '=';
        append(out, *value);
        out += ';';
      }
      out += '}';
      return;
    }
    case toml::node_type::array:
      out += '[';
      for (const toml::node& element : *node.as_array()) {
        append(out, element);
        out += ',';
      }
      out += ']';
      return;
    case toml::node_type::string:
      out += 's';
      appendSized(out, node.as_string()->get());
      return;
    case toml::node_type::integer: out += fmt::format("i{}", node.as_integer()->get()); return;
    case toml::node_type::floating_point: out += canonicalDouble(node.as_floating_point()->get()); return;
    case toml::node_type::boolean: out += node.as_boolean()->get() ? "b1" : "b0"; return;
    case toml::node_type::date: appendDate(out, node.as_date()->get()); return;
    case toml::node_type::time: appendTime(out, node.as_time()->get()); return;
    case toml::node_type::date_time: {
      const toml::date_time& dt = node.as_date_time()->get();
      out += "DT";
      appendDate(out, dt.date);
      appendTime(out, dt.time);
      if (dt.offset) out += fmt::format("Z{}", dt.offset->minutes);
      return;
    }
    case toml::node_type::none: out += 'n'; return;
  }
}

}  // namespace

std::string canonicalDouble(double value) {
  return fmt::format("f{:016x}", std::bit_cast<std::uint64_t>(value));
}

std::string canonicalToml(const toml::node& node) {
  std::string out;
  append(out, node);
  return out;
}

}  // namespace lattice::lht
