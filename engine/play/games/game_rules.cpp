#include "engine/play/games/game_rules.h"

#include <stdexcept>

#include "engine/play/games/ball_spotting.h"
#include "engine/play/games/eight_ball_rules.h"
#include "engine/play/games/rotation_rules.h"
#include "engine/play/games/snooker_rules.h"
#include "physics/value_text.h"

namespace baize::engine {

GameState initialGameState(Game game, const Table& table, const BallSet& balls,
                           const RackOptions& rack) {
  GameState state;
  state.game = game;
  state.balls = placeRack(gameName(game), table, balls, rack);
  if (game == Game::Snooker) {
    state.in_hand = CueBallInHand::InD;
    state.ball_on = "red";
  } else {
    state.in_hand = CueBallInHand::BehindHeadString;
  }
  return state;
}

std::vector<std::string> legalTargets(const GameState& state) {
  switch (state.game) {
    case Game::NineBall:
    case Game::TenBall:
      return {lowestBall(state)};
    case Game::EightBall:
      return eightBallTargets(state, state.player);
    case Game::Snooker:
      return snookerTargets(state);
  }
  return {};
}

std::string placementRefusal(const GameState& state, const Eigen::Vector2d& point_m,
                             const Table& table, double ball_radius_m) {
  const std::string where = "[" + physics::valueText(point_m.x()) + ", " +
                            physics::valueText(point_m.y()) + "]";
  switch (state.in_hand) {
    case CueBallInHand::No:
      return "the cue ball is not in hand";
    case CueBallInHand::BehindHeadString:
      if (!(point_m.x() <= table.pool_markings.value().head_string_x_m)) {
        return where + " is not behind the head string";
      }
      break;
    case CueBallInHand::InD: {
      const SnookerMarkings& m = table.snooker_markings.value();
      if (!(point_m.x() <= m.baulk_line_x_m && (point_m - m.brown_spot_m).norm() <= m.d_radius_m)) {
        return where + " is not in the D";
      }
      break;
    }
    case CueBallInHand::Anywhere:
      break;
  }
  std::vector<PlacedBall> others(state.balls.begin() + 1, state.balls.end());
  for (const PlacedBall& b : others) {
    if ((b.position_m - point_m).norm() < 2 * ball_radius_m) {
      return where + " touches ball " + b.id;
    }
  }
  if (!spotFree(others, point_m, table, ball_radius_m)) {
    return where + " is off the playing surface or frozen to a ball";
  }
  return "";
}

Ruling ruleShot(const GameState& state, const ShotFacts& facts, const ShotCall& call,
                const Table& table, double ball_radius_m) {
  if (state.frame_over) throw std::logic_error("a shot was ruled on after the frame was over");
  switch (state.game) {
    case Game::NineBall:
    case Game::TenBall:
      return ruleRotationShot(state, facts, call, table, ball_radius_m);
    case Game::EightBall:
      return ruleEightBallShot(state, facts, call, table, ball_radius_m);
    case Game::Snooker:
      return ruleSnookerShot(state, facts, call, table, ball_radius_m);
  }
  throw std::logic_error("unknown game");
}

}  // namespace baize::engine
