// Output files written whole: the bytes go to a temporary beside the target, renamed over it only
// once complete, so a reader never sees half a file and a failure leaves the old one. A symbolic
// link is followed (the file it names is replaced; the link stays). A device, FIFO or socket
// (/dev/stdout, a named pipe) cannot be replaced that way and is written straight, as a stream.
#pragma once

#include <string>

namespace baize::render {

struct WholeFileTarget {
  std::string path;     // the file to replace (the link's target for a symbolic link), or the stream
  bool stream = false;  // a device, FIFO or socket: written straight, no temporary
};

// Where an output named `path` goes. Throws std::invalid_argument when `path` is a directory (an
// output must name a file).
WholeFileTarget wholeFileTarget(const std::string& path);

// The temporary a whole-file write of `target` uses.
std::string temporaryFor(const WholeFileTarget& target);

}  // namespace baize::render
