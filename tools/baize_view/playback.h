// The viewer's clock: where in the shot it is, how fast it runs, whether traces show. Pure logic
// (no SDL), driven by key presses and elapsed wall time.
#pragma once

namespace baize::tools {

// Playback speeds: halved and doubled from 1 within these limits.
constexpr double kMinPlaybackSpeed = 1.0 / 16;
constexpr double kMaxPlaybackSpeed = 16;
// One press of left or right moves the shot this far, s.
constexpr double kScrubStep_s = 0.1;

class Playback {
 public:
  // `end_time_s` infinite: a shot still being simulated, whose end setEndTime() gives later.
  explicit Playback(double end_time_s = 0) : end_time_s_(end_time_s) {}
  void setEndTime(double end_time_s);

  // Runs the clock on by `wall_s` of real time times the speed, stopping at the end.
  void advance(double wall_s);
  void togglePlaying() { playing_ = !playing_; }
  void faster();
  void slower();
  // Moves by steps of kScrubStep_s (negative: back), clamped to the shot, and pauses.
  void scrub(int steps);
  // Back to the start, playing.
  void restart();
  void toggleTraces() { traces_ = !traces_; }

  double time_s() const { return time_s_; }
  double endTime_s() const { return end_time_s_; }
  double speed() const { return speed_; }
  bool playing() const { return playing_; }
  bool traces() const { return traces_; }
  bool atEnd() const { return time_s_ >= end_time_s_; }

 private:
  double end_time_s_ = 0;
  double time_s_ = 0;
  double speed_ = 1;
  bool playing_ = true;
  bool traces_ = true;
};

}  // namespace baize::tools
