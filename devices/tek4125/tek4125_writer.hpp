#pragma once
// Assembles 4100-series commands under one form set: xy in full or in the
// short forms, and every DEL (0x7F) inside a parameter sent as ESC ? when
// the set says so (RAL-CGM cgmtek.h does this after KI1, so a line that
// pads or strips DEL cannot corrupt a coordinate). Lengths are exposed so a
// planner can cost a choice without writing it.
//
// The writer holds at most about kSpillBytes: beyond that it escapes and
// hands what it has to its ByteSink, so a stream of any length costs the
// driver a fixed few KiB (the driver's memory bound, tek4125_device.cpp,
// counts on it).
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "devices/tek4125/tek4125_forms.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"
#include "foundation/byte_sink.hpp"

namespace lattice::tek4125 {

// LATTICE_TEK4125_SPILL_BYTES: what a build with little RAM holds instead
// (the firmware's 1 KiB, docs/firmware.md); the bytes sent are the same, in
// more pieces.
#ifndef LATTICE_TEK4125_SPILL_BYTES
#define LATTICE_TEK4125_SPILL_BYTES (16 * 1024)
#endif

class Tek4125Writer {
 public:
  static constexpr std::size_t kSpillBytes = LATTICE_TEK4125_SPILL_BYTES;

  // The buffer is reserved once: no doubling leaves twice kSpillBytes held.
  Tek4125Writer(const Tek4125Forms& forms, ByteSink& sink) : forms_(forms), sink_(sink) {
    out_.reserve(kSpillBytes + kLongestPiece);
  }

  void command(std::string_view name) {
    tek4125::appendCommand(out_, name);
    pixelCommand_ = name == "RR" || name == "RH";
    spillIfFull();
  }
  void integer(int value);
  void xy(int x, int y);
  void byte(std::uint8_t c) {
    out_.push_back(c);
    spillIfFull();
  }
  void bytes(std::initializer_list<std::uint8_t> cs) {
    for (std::uint8_t c : cs) out_.push_back(c);  // (GCC 12 warns falsely on insert into an empty vector)
    spillIfFull();
  }

  // Bytes of the stream so far, DELs escaped: handed on plus still held.
  std::uint64_t size() const { return spilled_ + out_.size() + dels_; }
  const Tek4125Forms& forms() const { return forms_; }
  // Hands every byte still held to the sink (the stream is complete).
  void finish() { spill(); }

 private:
  // OpenVnmrJ's short form applies between xys of RR and RH only.
  bool highShortNow() const { return forms_.shortHighXy && pixelCommand_ && lastXyInPixelCommand_; }
  void spillIfFull() {
    if (out_.size() >= kSpillBytes) spill();
  }
  void spill();
  void countDels(std::size_t from);
  // More than one call adds between spills (a command name, an integer, an xy).
  static constexpr std::size_t kLongestPiece = 64;

  const Tek4125Forms& forms_;
  ByteSink& sink_;
  tek4125::XyEncoder xy_;
  bool pixelCommand_ = false;          // the command being written is RR or RH
  bool lastXyInPixelCommand_ = false;  // the last xy sent belonged to one
  tek4125::Bytes out_;      // not yet handed on, DELs not yet escaped
  std::size_t dels_ = 0;    // DELs in out_: the bytes escaping will add, so size() is exact
  std::uint64_t spilled_ = 0;
};

}  // namespace lattice::tek4125
