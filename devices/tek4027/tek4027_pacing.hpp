#pragma once
// Report pacing for the 4027. Method: the UGS maintenance manual (ugintdoc,
// section 9.16) says the terminal accepts data faster than it can draw and
// overflows its buffer without any sign but a scrambled picture, and that
// UGS therefore ends every record with a report request (`!REP 00`) and
// sends the next record only after the answer. We cut the finished stream
// at command boundaries into records of at most `recordBytes` bytes (a single
// longer command stays whole) and end each with `!REP 00` and CR.
//
// Tunables (Tek4027Profile): pacing (none | report | auto: report only when
// the stream is longer than one record), recordBytes (504, UGS's own buffer).
//
// Over a one-way transport (a file, stdout) the requests are simply part of
// the stream. Over a serial line the driver is given a Tek4027Replies and
// waits for one answer after each record.
#include <cstddef>
#include <string>
#include <vector>

#include "devices/tek4027/tek4027_profile.hpp"

namespace lattice::tek4027 {

// Something that can wait for the terminal's answer to one report request
// (the serial line's input). Throws lattice::Error when none comes in time.
class Tek4027Replies {
 public:
  virtual ~Tek4027Replies() = default;
  virtual void awaitReply() = 0;
};

// The replies on a file descriptor (a serial port's, opened read-write): a
// reply is whatever the terminal sends up to and including a CR (the
// sources do not give the report's content, only that one comes). Throws
// lattice::Error(Stalled) after `timeoutSeconds` without a whole reply.
class Tek4027FdReplies final : public Tek4027Replies {
 public:
  Tek4027FdReplies(int fd, double timeoutSeconds) : fd_(fd), timeoutSeconds_(timeoutSeconds) {}
  void awaitReply() override;
  std::size_t repliesSeen() const { return seen_; }

 private:
  int fd_;
  double timeoutSeconds_;
  std::size_t seen_ = 0;
};

// Where the records of an unpaced stream end: offsets into `text` at which
// a request goes. Empty when the profile does not pace the stream.
std::vector<std::size_t> recordCuts(const std::string& text, const Tek4027Profile& profile);

// The stream's length once paced, without building it (Shortest compares
// paced lengths but keeps only one unpaced candidate besides the best).
std::size_t pacedSize(const std::string& text, const std::vector<std::size_t>& cuts, const Tek4027Profile& profile);

// Where the records of a paced stream end (just past each request's CR).
std::vector<std::size_t> reportRecordEnds(const std::string& paced, const Tek4027Profile& profile);

// `text` is a finished stream (commands introduced by profile.commandChar).
// Returns it unchanged when the profile does not pace it.
std::string paceWithReports(std::string text, const Tek4027Profile& profile);

}  // namespace lattice::tek4027
