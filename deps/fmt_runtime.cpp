// The compiled half of fmt, built once for every target of ours.
//
// Method and tunables: fmt has two forms, header-only (FMT_HEADER_ONLY: every
// translation unit that formats compiles the formatting engine again) and a
// library (the engine compiled once, format.h declaring it). Debian ships the
// library only as libfmt.so, which pulls in the shared libstdc++ that
// `lattice` leaves out (LATTICE_STATIC_CXX, docs/memory.md), so until now
// every object was compiled header-only: measured on foundation/progress.cpp,
// about 2.7 times the compile time of the library form (docs/benchmarks.md,
// "Build time"). Here the engine is compiled once from Debian's own headers:
// format-inl.h defines every non-template function (FMT_FUNC is empty outside
// the header-only form), and the lines below instantiate the templates that
// format.h declares `extern template` or leaves undefined, for the character
// type we use. A missing one is a link error naming it, never a silent fault.
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {
template auto dragonbox::to_decimal(float x) noexcept -> dragonbox::decimal_fp<float>;
template auto dragonbox::to_decimal(double x) noexcept -> dragonbox::decimal_fp<double>;
template auto thousands_sep_impl<char>(locale_ref) -> thousands_sep_result<char>;
template auto decimal_point_impl(locale_ref) -> char;
template locale_ref::locale_ref(const std::locale& loc);
template auto locale_ref::get<std::locale>() const -> std::locale;
}  // namespace detail
FMT_END_NAMESPACE
