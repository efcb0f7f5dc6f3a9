// A text file that appears complete or not at all: the content goes to "<path>.tmp", which is
// renamed to <path> by commit(). The temporary is created by the constructor, so an unwritable path
// fails before any work is done, and it is removed again if commit() is never reached. As for every
// output (engine/io/whole_file.h), a symbolic link is followed and a device or FIFO is written
// straight.
#pragma once

#include <fstream>
#include <string>

#include "engine/io/whole_file.h"

namespace baize::tools {

// Where the output `flag` names at `path` goes (engine::wholeFileTarget); a path no output can be
// written to (a directory, a loop of links, a named pipe no program reads) is refused with a
// UsageError naming the flag.
engine::WholeFileTarget outputTarget(const std::string& flag, const std::string& path);

// Checks before any work that an output the writers of render/ will write whole can be written at
// `path`: makes its parent folders, refuses a directory, and creates (and removes) the temporary
// of a file. Throws UsageError naming `flag` and the path.
void checkOutputPath(const std::string& flag, const std::string& path);

class AtomicFile {
 public:
  // `origin` says where the path came from (e.g. "--csv"), for error messages. Missing parent
  // folders are made, as checkOutputPath makes them.
  // Throws UsageError when the path is a directory and std::runtime_error when the temporary
  // cannot be created.
  AtomicFile(std::string path, std::string origin);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  // Flushes, closes and renames into place; throws std::runtime_error when any of it fails.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what) const;

  std::string path_;    // as given, for messages
  std::string origin_;  // the flag that named it (initialised before target_, which names it)
  engine::WholeFileTarget target_;
  std::string temporary_path_;  // the file written: the temporary, or the stream itself
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace baize::tools
