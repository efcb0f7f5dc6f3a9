#include "tools/baize_view/playback.h"

#include <gtest/gtest.h>

#include <limits>

namespace baize::tools {
namespace {

TEST(Playback, RunsAtItsSpeedAndStopsAtTheEnd) {
  Playback playback(2.0);
  playback.advance(0.5);
  EXPECT_DOUBLE_EQ(playback.time_s(), 0.5);
  playback.faster();  // x2
  playback.advance(0.5);
  EXPECT_DOUBLE_EQ(playback.time_s(), 1.5);
  playback.advance(10);
  EXPECT_DOUBLE_EQ(playback.time_s(), 2.0);
  EXPECT_TRUE(playback.atEnd());
  playback.restart();
  EXPECT_DOUBLE_EQ(playback.time_s(), 0.0);
  EXPECT_TRUE(playback.playing());
}

TEST(Playback, PausedClockStandsStill) {
  Playback playback(3.0);
  playback.togglePlaying();
  playback.advance(1.0);
  EXPECT_DOUBLE_EQ(playback.time_s(), 0.0);
  playback.togglePlaying();
  playback.advance(1.0);
  EXPECT_DOUBLE_EQ(playback.time_s(), 1.0);
}

TEST(Playback, SpeedStaysWithinItsLimits) {
  Playback playback(1.0);
  for (int i = 0; i < 20; ++i) playback.faster();
  EXPECT_DOUBLE_EQ(playback.speed(), kMaxPlaybackSpeed);
  for (int i = 0; i < 40; ++i) playback.slower();
  EXPECT_DOUBLE_EQ(playback.speed(), kMinPlaybackSpeed);
}

TEST(Playback, ScrubPausesAndStaysWithinTheShot) {
  Playback playback(0.35);
  playback.scrub(2);
  EXPECT_FALSE(playback.playing());
  EXPECT_DOUBLE_EQ(playback.time_s(), 2 * kScrubStep_s);
  playback.scrub(5);
  EXPECT_DOUBLE_EQ(playback.time_s(), 0.35);
  playback.scrub(-100);
  EXPECT_DOUBLE_EQ(playback.time_s(), 0.0);
  playback.toggleTraces();
  EXPECT_FALSE(playback.traces());
}

}  // namespace
// A shot still being stepped has no end yet; once it has one, the clock stops there (and comes
// back to it if it had run past).
TEST(Playback, AnEndGivenLaterStopsTheClock) {
  Playback playback(std::numeric_limits<double>::infinity());
  playback.advance(3);
  EXPECT_DOUBLE_EQ(playback.time_s(), 3.0);
  EXPECT_FALSE(playback.atEnd());
  playback.setEndTime(2.5);
  EXPECT_DOUBLE_EQ(playback.time_s(), 2.5);
  EXPECT_TRUE(playback.atEnd());
  playback.advance(1);
  EXPECT_DOUBLE_EQ(playback.time_s(), 2.5);
}

}  // namespace baize::tools
