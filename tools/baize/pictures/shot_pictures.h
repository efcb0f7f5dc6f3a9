// The pictures the picture flags of `baize render` and `baize simulate` ask for
// (tools/baize/picture_flags.h): one PNG of the shot at a time (the end by default), numbered PNG
// frames of it in real time, and/or an animated GIF of the same frames.
#pragma once

#include "render/shot_record.h"
#include "tools/baize/picture_flags.h"

namespace baize::tools {

// The most frames one command writes (an hour at 30 frames a second would be far beyond any shot).
constexpr long kMaxFrames = 20000;

// Checks every flag and that the outputs can be created (making missing parent folders), before
// any simulation or drawing; throws UsageError naming the flag otherwise.
void checkPictureFlags(const PictureFlags& flags);

// Draws and writes what the flags ask for; prints one line per file (frames: one line in all).
void writePictures(const render::ShotRecord& shot, const PictureFlags& flags);

}  // namespace baize::tools
