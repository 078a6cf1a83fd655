#pragma once
// The table forms, one list: `LhtTable` below. A form is a class in
// lht/table/ (hash_table.hpp, compressed_table.hpp, on_demand_table.hpp)
// that every other part of Lattice reaches through this list, never by name,
// so a new form is its files here and one alternative in LhtTable. Its
// position in the list is its LhtForm code (lht/table/lht_form.hpp, the code a
// version-3 .lht header holds at byte 108); the enum names only the forms
// code refers to.
//
// What a form provides (checked by the concepts below):
// * kFormName, kFormSummary: its name (`--lht-form`, a scene's `form`) and
//   what `lattice lht-info` says it is;
// * precision(), entryCount(), bytes(), findPayload(in, out): the look-up a
//   render makes, the payload's bytes or null (lht/leaf/table_lookup.hpp);
// * fromHits(hits, cells, precision) if it is built by rasterizing
//   (loader/table_build.hpp), and describe(hits) for lht-info's lines;
// * if .lht files hold it (version 3: LhtBodyHeader's numbers in the header,
//   then its body): bodyHeader(), appendBody(out), bodyBytes(header, room)
//   (the body's size the header implies, or Error(Input) saying why not)
//   and fromBody(header, body). The hashed form is the exception that came
//   first: version 4 (and the thesis's chained versions 1-3) are its own
//   layouts, read and written by lht/file/lht_file.cpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "lht/table/compressed_table.hpp"
#include "lht/table/hash_table.hpp"
#include "lht/table/lht_form.hpp"
#include "lht/table/on_demand_table.hpp"

namespace lattice::lht {

// The on-demand table is shared: it grows while several renders read it.
using OnDemandTableRef = std::shared_ptr<const OnDemandTable>;

// The list. A new form: one alternative here, at the end.
using LhtTable = std::variant<LatticeHashTable, CompressedTable, OnDemandTableRef>;

inline constexpr std::size_t kLhtFormCount = std::variant_size_v<LhtTable>;

// The table object behind an alternative.
template <class Table>
const Table& formTable(const Table& table) {
  return table;
}
template <class Table>
const Table& formTable(const std::shared_ptr<const Table>& table) {
  return *table;
}

// The form class behind alternative I: what formTable gives for it.
template <std::size_t I>
using FormAt = std::remove_cvref_t<decltype(formTable(std::declval<const std::variant_alternative_t<I, LhtTable>&>()))>;

// Built by rasterizing; kept in .lht files (version 3).
template <class Form>
concept RasterizedForm = requires(const RasterHits& hits, const std::array<int, 3>& cells, LhtPrecision p) {
  { Form::fromHits(hits, cells, p) } -> std::same_as<Form>;
};
template <class Form>
concept FiledForm = requires(const Form& form, std::vector<std::uint8_t>& out, const LhtBodyHeader& h) {
  { form.bodyHeader() } -> std::same_as<LhtBodyHeader>;
  form.appendBody(out);
  { Form::bodyBytes(h, std::uint64_t{}) } -> std::same_as<std::uint64_t>;
  { Form::fromBody(h, std::vector<std::uint8_t>{}) } -> std::same_as<Form>;
};

// Calls f(std::integral_constant<std::size_t, I>) for the form whose code is
// `form` and returns what it returns; `otherwise()` for a code past the list.
template <class F, class Otherwise>
decltype(auto) withForm(LhtForm form, F&& f, Otherwise&& otherwise) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) -> decltype(auto) {
    using R = decltype(f(std::integral_constant<std::size_t, 0>{}));
    if constexpr (std::is_void_v<R>) {
      if (!((static_cast<std::size_t>(form) == I ? (f(std::integral_constant<std::size_t, I>{}), true) : false) ||
            ...))
        otherwise();
    } else {
      R result{};
      if (!((static_cast<std::size_t>(form) == I ? (result = f(std::integral_constant<std::size_t, I>{}), true)
                                                 : false) ||
            ...))
        result = otherwise();
      return result;
    }
  }(std::make_index_sequence<kLhtFormCount>{});
}

// Every form's name, in code order.
inline constexpr std::array<std::string_view, kLhtFormCount> kLhtFormNames =
    []<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<std::string_view, kLhtFormCount>{FormAt<I>::kFormName...};
    }(std::make_index_sequence<kLhtFormCount>{});

}  // namespace lattice::lht
