// Hand-made shots for the rules tests: the balls of a state, the events a referee would see (ball
// contacts, cushions, pockets) listed by hand, and the facts read from them by shotFacts, as from
// a simulated run. No simulation.
#pragma once

#include <string>
#include <vector>

#include "engine/io/ball_set.h"
#include "engine/io/table.h"
#include "engine/play/games/game_state.h"
#include "engine/play/games/shot_facts.h"

namespace baize::engine::test {

inline const Table& poolTable() {
  static const Table table = builtinTable("pool-9ft");
  return table;
}
inline const Table& snookerTable() {
  static const Table table = builtinTable("snooker-12ft");
  return table;
}
inline double poolRadius() { return builtinBallSet("pool").radius_m; }
inline double snookerRadius() { return builtinBallSet("snooker").radius_m; }

// A state of `game` with these balls (the cue ball first), player 0 to play, not a break.
inline GameState stateWith(Game game, const std::vector<PlacedBall>& balls) {
  GameState s;
  s.game = game;
  s.balls = balls;
  s.break_shot = false;
  if (game == Game::Snooker) s.ball_on = "red";
  return s;
}

class HandMadeShot {
 public:
  explicit HandMadeShot(const GameState& state) {
    for (const PlacedBall& b : state.balls) {
      ids_.push_back(b.id);
      BallRecord r;
      r.state.position = b.position_m;
      result_.final_balls.push_back(r);
    }
  }
  HandMadeShot& hit(const std::string& a, const std::string& b) {
    return add(EventKind::BallBall, index(a), index(b), -1);
  }
  HandMadeShot& cushion(const std::string& id) { return add(EventKind::Cushion, index(id), -1, 0); }
  HandMadeShot& pocket(const std::string& id, int pocket) {
    result_.final_balls[index(id)].pocketed = true;
    result_.final_balls[index(id)].pocket = pocket;
    return add(EventKind::Pocket, index(id), -1, pocket);
  }
  HandMadeShot& moveTo(const std::string& id, Eigen::Vector2d to) {
    result_.final_balls[index(id)].state.position = to;
    return *this;
  }
  HandMadeShot& offTable(const std::string& id) {
    off_table_.push_back(id);
    return *this;
  }
  ShotFacts facts() const {
    ShotFacts f = shotFacts(ids_, result_, "cue");
    f.off_table = off_table_;
    std::vector<PlacedBall> kept;
    for (const PlacedBall& b : f.final_balls) {
      if (!f.offTable(b.id)) kept.push_back(b);
    }
    f.final_balls = kept;
    return f;
  }

 private:
  int index(const std::string& id) const {
    for (std::size_t i = 0; i < ids_.size(); ++i) {
      if (ids_[i] == id) return static_cast<int>(i);
    }
    throw std::invalid_argument("no ball " + id + " in the hand-made shot");
  }
  HandMadeShot& add(EventKind kind, int ball, int other, int idx) {
    Event e;
    e.kind = kind;
    e.ball = ball;
    e.other = other;
    e.index = idx;
    result_.events.push_back(e);
    return *this;
  }
  std::vector<std::string> ids_;
  SimulationResult result_;
  std::vector<std::string> off_table_;
};

}  // namespace baize::engine::test
