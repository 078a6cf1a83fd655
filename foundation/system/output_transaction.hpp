#pragma once
// A command's outputs (its stream, its PNG, the --at snapshots, a recording)
// land together or not at all.
//
// Method: while a transaction is open, AtomicFile::close() writes and fsyncs
// its temporary but does not rename it: the transaction keeps it, still in the
// signal-safe registry (temp_file_registry.hpp), so SIGINT, SIGTERM or SIGHUP
// unlink it as before. commit() renames every kept temporary into place in
// the order they were closed; leaving the scope without commit() (an error, an
// exception) unlinks them all, so the files a user had are untouched. Renames
// within one directory do not fail for want of space, and every target was
// probed before the command's work began (app/output_check.hpp), so the
// window where only some files have landed is the few microseconds of the
// renames. Files that are caches, not outputs (a lattice's .lht beside its
// scene), say AtomicFile::Landing::Now and land when closed.
// One transaction is open at a time; the command line opens it around a command.
#include <filesystem>
#include <vector>

namespace lattice {

class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();  // discards what was not committed
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Renames every kept file into place; Error(Output) if one cannot be
  // (the rest are still renamed: each file is whole either way).
  void commit();
  // Commits the open transaction now, if there is one: for a command whose
  // first half's outputs must land before its second half starts
  // (`render --port` records the stream, then sends the file, so a send that
  // stops can be resumed from it).
  static void commitOpen();
  std::size_t pending() const;  // kept and not yet renamed
  // The targets kept so far, in order: what a failed command says it did not write.
  std::vector<std::filesystem::path> pendingTargets() const;

  // For AtomicFile::close(): when a transaction is open it takes the closed
  // temporary and its registry slot and returns true; otherwise false.
  static bool keep(const std::filesystem::path& temp, const std::filesystem::path& target, int registrySlot);

 private:
  struct Kept {
    std::filesystem::path temp, target;
    int slot = -1;
  };
  std::vector<Kept> kept_;
  OutputTransaction* outer_ = nullptr;
};

}  // namespace lattice
