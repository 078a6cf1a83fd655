#include "foundation/system/output_transaction.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>

#include "foundation/error.hpp"
#include "foundation/system/temp_file_registry.hpp"

namespace lattice {
namespace {

// Workers may close files too (a band's writer); one lock covers the list.
std::mutex gLock;
OutputTransaction* gOpen = nullptr;

}  // namespace

OutputTransaction::OutputTransaction() {
  const std::lock_guard lock(gLock);
  outer_ = gOpen;  // a nested one (a test inside a command) keeps its own files
  gOpen = this;
}

OutputTransaction::~OutputTransaction() {
  const std::lock_guard lock(gLock);
  for (const Kept& k : kept_) {
    ::unlink(k.temp.c_str());
    TempFileRegistry::remove(k.slot);
  }
  kept_.clear();
  if (gOpen == this) gOpen = outer_;
}

std::size_t OutputTransaction::pending() const {
  const std::lock_guard lock(gLock);
  return kept_.size();
}

std::vector<std::filesystem::path> OutputTransaction::pendingTargets() const {
  const std::lock_guard lock(gLock);
  std::vector<std::filesystem::path> targets;
  for (const Kept& k : kept_) targets.push_back(k.target);
  return targets;
}

bool OutputTransaction::keep(const std::filesystem::path& temp, const std::filesystem::path& target, int registrySlot) {
  const std::lock_guard lock(gLock);
  if (gOpen == nullptr) return false;
  // The same target closed twice (a snapshot named like the picture) keeps the last.
  for (Kept& k : gOpen->kept_)
    if (k.target == target) {
      ::unlink(k.temp.c_str());
      TempFileRegistry::remove(k.slot);
      k = {temp, target, registrySlot};
      return true;
    }
  gOpen->kept_.push_back({temp, target, registrySlot});
  return true;
}

void OutputTransaction::commit() {
  const std::lock_guard lock(gLock);
  std::string failed;
  for (const Kept& k : kept_) {
    if (::rename(k.temp.c_str(), k.target.c_str()) != 0) {
      if (failed.empty())
        failed = fmt::format("{}: cannot rename the finished file into place: {}", k.target.string(), std::strerror(errno));
      ::unlink(k.temp.c_str());
    }
    TempFileRegistry::remove(k.slot);
  }
  kept_.clear();
  if (!failed.empty()) throw Error(ErrorKind::Output, failed);
}

void OutputTransaction::commitOpen() {
  OutputTransaction* open = nullptr;
  {
    const std::lock_guard lock(gLock);
    open = gOpen;
  }
  if (open) open->commit();
}

}  // namespace lattice
