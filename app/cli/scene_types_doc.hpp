#pragma once
// The table of object types in docs/scene-format.md, made from the loader
// itself so that it cannot drift from what a scene file may say.
//
// Method: the node parsers keep their keys inside their own code (each
// calls ParseContext::checkKeys first), so the table is read by asking the
// loader that a scene file meets, lattice module included
// (lht::parseSceneWithLattices): an object of an unknown type lists every
// type, and an object of each type with one unknown key lists that type's
// keys. Keys every type takes (type, name, material and the transform) are
// listed once, apart. tests/app/scene_types_doc_test.cpp compares the
// table with the one in the doc (and rewrites it with
// LATTICE_REGENERATE_GOLDENS=1).
#include <string>
#include <vector>

namespace lattice::app {

struct NodeTypeKeys {
  std::string type;
  std::vector<std::string> keys;  // its own keys, in the parser's order
};

struct NodeTypeTable {
  std::vector<NodeTypeKeys> types;  // in the loader's (alphabetical) order
  std::vector<std::string> common;  // keys every type takes
};

NodeTypeTable nodeTypeTable();
// The Markdown table, one row per type.
std::string nodeTypeMarkdown(const NodeTypeTable& table);

}  // namespace lattice::app
