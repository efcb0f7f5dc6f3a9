#include "tools/baize/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace baize::tools {

AtomicFile::AtomicFile(std::string path, std::string origin)
    : path_(std::move(path)), temporary_path_(path_ + ".tmp"), origin_(std::move(origin)) {
  errno = 0;
  out_.open(temporary_path_, std::ios::out | std::ios::trunc);
  if (!out_) fail("cannot create '" + temporary_path_ + "'");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::remove(temporary_path_.c_str());
}

void AtomicFile::commit() {
  errno = 0;
  out_.flush();
  if (!out_) fail("cannot write '" + temporary_path_ + "'");
  out_.close();
  if (out_.fail()) fail("cannot close '" + temporary_path_ + "'");
  // std::rename replaces an existing file atomically on POSIX systems.
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    fail("cannot rename '" + temporary_path_ + "' to '" + path_ + "'");
  }
  committed_ = true;
}

void AtomicFile::fail(const std::string& what) const {
  const std::string reason = errno != 0 ? std::string(": ") + std::strerror(errno) : std::string();
  throw std::runtime_error(origin_ + " = " + path_ + ": " + what + reason);
}

}  // namespace baize::tools
