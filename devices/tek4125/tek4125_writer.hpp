#pragma once
// Assembles 4100-series commands under one form set: xy in full or in the
// short forms, and every DEL (0x7F) inside a parameter sent as ESC ? when
// the set says so (RAL-CGM cgmtek.h does this after KI1, so a line that
// pads or strips DEL cannot corrupt a coordinate). Lengths are exposed so a
// planner can cost a choice without writing it.
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "devices/tek4125/tek4125_forms.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"

namespace lattice::tek4125 {

class Tek4125Writer {
 public:
  explicit Tek4125Writer(const Tek4125Forms& forms) : forms_(forms) {}

  void command(std::string_view name) { tek4125::appendCommand(out_, name); }
  void integer(int value);
  void xy(int x, int y);
  void byte(std::uint8_t c) { out_.push_back(c); }
  void bytes(std::initializer_list<std::uint8_t> cs) {
    for (std::uint8_t c : cs) out_.push_back(c);  // (GCC 12 warns falsely on insert into an empty vector)
  }

  // Bytes xy() would write now.
  int xyLength(int x, int y) const { return forms_.fullXy ? 5 : xy_.length(x, y); }
  std::size_t size() const { return out_.size() + dels_; }
  const Tek4125Forms& forms() const { return forms_; }
  // The stream so far, DELs escaped as the form set asks; the writer is left empty.
  tek4125::Bytes take();

 private:
  const Tek4125Forms& forms_;
  tek4125::XyEncoder xy_;
  tek4125::Bytes out_;
  void countDels(std::size_t from);
  std::size_t dels_ = 0;  // extra bytes take() will add, so size() is exact
};

}  // namespace lattice::tek4125
