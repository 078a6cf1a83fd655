#include "app/output_check.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "foundation/error.hpp"
#include "foundation/system/atomic_file.hpp"

namespace lattice::app {

void checkOutputPath(const std::string& path, const std::string& flag, bool force) {
  if (path.empty() || path == "-") return;
  const std::filesystem::path parent = std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec))
    throw Error(ErrorKind::Output, fmt::format("{} {}: the directory {} does not exist; create it or choose another path",
                                               flag, path, parent.string()));
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) {
    if (S_ISDIR(info.st_mode))
      throw Error(ErrorKind::Output,
                  fmt::format("{} {}: is a directory; give a file name, e.g. {}/out.png", flag, path, path));
    const bool readOnly = (info.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(path.c_str(), W_OK) != 0;
    if (readOnly && !force)
      throw Error(ErrorKind::Output, fmt::format("{} {}: the file is read-only; add --force to replace it, or "
                                                 "choose another path",
                                                 flag, path));
  }
  // The outputs are written as a temporary beside the file, then renamed
  // (foundation/system/atomic_file.hpp): the same temporary is made now and
  // discarded. It is registered like every other, so a signal arriving
  // meanwhile leaves nothing behind (tests/app/killed_writer_test.cpp).
  try {
    const AtomicFile probe(path);
  } catch (const Error&) {
    const int reason = errno;  // the failed open's, which the error carries too
    throw Error(ErrorKind::Output, fmt::format("{} {}: cannot write in {}: {}; choose a directory you can write to",
                                               flag, path, parent.string(), std::strerror(reason)));
  }
}

namespace {

// An option checked with CLI::ExistingFile reads a file (`term --stream`
// plays one): it is an input, whatever its name. Read from the type name,
// where CLI11 appends each validator's description (":FILE" for that one),
// not from get_validator, which throws for every option without it: the
// first exception a static build throws makes the unwinder read all of
// .eh_frame and keep a sorted index of it on the heap (docs/memory.md).
bool namesExistingFile(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  const std::string_view marker = ":FILE";
  return type.size() >= marker.size() && std::string_view(type).substr(type.size() - marker.size()) == marker;
}

}  // namespace

void guardOutputs(CLI::App& root) {
  for (CLI::App* command : root.get_subcommands([](const CLI::App*) { return true; })) {
    guardOutputs(*command);
    std::vector<CLI::Option*> outputs;
    for (const char* name : {"--output", "--stream", "--snapshot", "--record"})
      if (CLI::Option* option = command->get_option_no_throw(name); option && !namesExistingFile(*option))
        outputs.push_back(option);
    if (outputs.empty()) continue;
    CLI::Option* force = command->get_option_no_throw("--force");
    if (force == nullptr)
      force = command->add_flag("--force")
                  ->description("Replace output files even if they are read-only")
                  ->group(outputs[0]->get_group());
    command->parse_complete_callback([outputs, force] {
      for (const CLI::Option* option : outputs)
        for (const std::string& path : option->results()) checkOutputPath(path, option->get_name(), force->count() > 0);
    });
  }
}

}  // namespace lattice::app
