#include "tools/baize/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "tools/baize/cli_errors.h"

namespace baize::tools {

engine::WholeFileTarget outputTarget(const std::string& flag, const std::string& path) {
  try {
    return engine::wholeFileTarget(path);
  } catch (const std::invalid_argument& refused) {
    throw UsageError(flag + " = " + path + " is not allowed: " + refused.what());
  }
}

void checkOutputPath(const std::string& flag, const std::string& path) {
  try {
    engine::prepareWholeFile(path);
  } catch (const std::invalid_argument& refused) {
    throw UsageError(flag + " = " + path + " is not allowed: " + refused.what());
  }
}

AtomicFile::AtomicFile(std::string path, std::string origin)
    : path_(std::move(path)), origin_(std::move(origin)), target_(outputTarget(origin_, path_)) {
  temporary_path_ = target_.stream ? target_.path : engine::temporaryFor(target_);
  if (!target_.stream) engine::makeParentFolders(target_.path);
  errno = 0;
  out_.open(temporary_path_, std::ios::out | (target_.stream ? std::ios::app : std::ios::trunc));
  if (!out_) fail("cannot create '" + temporary_path_ + "'");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  if (!target_.stream) std::remove(temporary_path_.c_str());
}

void AtomicFile::commit() {
  errno = 0;
  out_.flush();
  if (!out_) fail("cannot write '" + temporary_path_ + "'");
  out_.close();
  if (out_.fail()) fail("cannot close '" + temporary_path_ + "'");
  // std::rename replaces an existing file atomically on POSIX systems.
  if (!target_.stream && std::rename(temporary_path_.c_str(), target_.path.c_str()) != 0) {
    fail("cannot rename '" + temporary_path_ + "' to '" + target_.path + "'");
  }
  committed_ = true;
}

void AtomicFile::fail(const std::string& what) const {
  const std::string reason = errno != 0 ? std::string(": ") + std::strerror(errno) : std::string();
  throw std::runtime_error(origin_ + " = " + path_ + ": " + what + reason);
}

}  // namespace baize::tools
