// A text file that appears complete or not at all: the content goes to "<path>.tmp", which is
// renamed to <path> by commit(). The temporary is created by the constructor, so an unwritable path
// fails before any work is done, and it is removed again if commit() is never reached.
#pragma once

#include <fstream>
#include <string>

namespace baize::tools {

class AtomicFile {
 public:
  // `origin` says where the path came from (e.g. "--csv"), for error messages.
  // Throws std::runtime_error when the temporary cannot be created.
  AtomicFile(std::string path, std::string origin);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  // Flushes, closes and renames into place; throws std::runtime_error when any of it fails.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what) const;

  std::string path_;
  std::string temporary_path_;
  std::string origin_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace baize::tools
