#include "tools/baize_view/playback.h"

#include <algorithm>

namespace baize::tools {

void Playback::advance(double wall_s) {
  if (!playing_ || !(wall_s > 0)) return;
  time_s_ = std::min(end_time_s_, time_s_ + wall_s * speed_);
}

void Playback::setEndTime(double end_time_s) {
  end_time_s_ = end_time_s;
  time_s_ = std::min(time_s_, end_time_s_);
}

void Playback::faster() { speed_ = std::min(kMaxPlaybackSpeed, speed_ * 2); }
void Playback::slower() { speed_ = std::max(kMinPlaybackSpeed, speed_ / 2); }

void Playback::scrub(int steps) {
  time_s_ = std::clamp(time_s_ + steps * kScrubStep_s, 0.0, end_time_s_);
  playing_ = false;
}

void Playback::restart() {
  time_s_ = 0;
  playing_ = true;
}

}  // namespace baize::tools
