// Output files written whole: the bytes go to a temporary beside the target, renamed over it only
// once complete, so a reader never sees half a file and a failure leaves the old one. A symbolic
// link is followed (the file it names is replaced; the link stays). A device, a named pipe or an
// open descriptor (/dev/stdout, /dev/fd/N) cannot be replaced that way and is written straight,
// appended to (so `--json /dev/stdout >> log` keeps what the log held).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace baize::engine {

struct WholeFileTarget {
  std::string path;     // the file to replace (the link's target for a symbolic link), or the stream
  bool stream = false;  // a device, pipe or descriptor: written straight (appended), no temporary
};

// The path that names standard output for every output ("--json -").
constexpr const char* kStandardOutputPath = "-";

// Where an output named `path` goes ("-": standard output, written straight). Throws std::invalid_argument saying why (without the path)
// when it is a directory, a loop of symbolic links, or a named pipe no program reads (writing
// would wait forever).
WholeFileTarget wholeFileTarget(const std::string& path);

// The temporary a whole-file write of `target` uses.
std::string temporaryFor(const WholeFileTarget& target);

// Makes the missing parent folders of an output at `path` (the rule for every output); returns
// the error, if any, for the caller's message.
std::error_code makeParentFolders(const std::string& path);

// Checks before any work that a whole file can be written at `path`, by the one rule every output
// follows: its missing parent folders are made, and its temporary is created and removed again.
// Throws std::invalid_argument saying why (without the path) when it cannot be.
void prepareWholeFile(const std::string& path);

// Writes `bytes` to `path` whole, as above; throws std::runtime_error naming the path when it
// cannot, leaving no temporary behind.
void writeWholeFile(const std::vector<std::uint8_t>& bytes, const std::string& path);

}  // namespace baize::engine
