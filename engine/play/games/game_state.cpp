#include "engine/play/games/game_state.h"

#include <algorithm>

namespace baize::engine {

const char* gameName(Game game) {
  switch (game) {
    case Game::NineBall:
      return "9-ball";
    case Game::TenBall:
      return "10-ball";
    case Game::EightBall:
      return "8-ball";
    case Game::Snooker:
      return "snooker";
  }
  return "?";
}

std::vector<std::string> gameNames() { return {"9-ball", "10-ball", "8-ball", "snooker"}; }

std::optional<Game> gameNamed(const std::string& name) {
  for (Game g : {Game::NineBall, Game::TenBall, Game::EightBall, Game::Snooker}) {
    if (name == gameName(g)) return g;
  }
  return std::nullopt;
}

const char* inHandName(CueBallInHand in_hand) {
  switch (in_hand) {
    case CueBallInHand::No:
      return "no";
    case CueBallInHand::BehindHeadString:
      return "behind head string";
    case CueBallInHand::Anywhere:
      return "anywhere";
    case CueBallInHand::InD:
      return "in the D";
  }
  return "?";
}

const char* groupName(Group group) {
  switch (group) {
    case Group::None:
      return "open";
    case Group::Solids:
      return "solids";
    case Group::Stripes:
      return "stripes";
  }
  return "?";
}

const char* gameFoulName(GameFoul foul) {
  switch (foul) {
    case GameFoul::None:
      return "none";
    case GameFoul::CueBallPocketed:
      return "cue ball pocketed";
    case GameFoul::NoBallHit:
      return "no ball hit";
    case GameFoul::WrongBallFirst:
      return "wrong ball first";
    case GameFoul::NoCushionAfterContact:
      return "no cushion after contact";
    case GameFoul::BallOffTable:
      return "ball off table";
    case GameFoul::BallNotOnPotted:
      return "ball not on potted";
    case GameFoul::IllegalBreak:
      return "illegal break";
  }
  return "?";
}

const PlacedBall* GameState::ball(const std::string& id) const {
  for (const PlacedBall& b : balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

bool operator==(const GameState& a, const GameState& b) {
  if (a.balls.size() != b.balls.size()) return false;
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    if (a.balls[i].id != b.balls[i].id || a.balls[i].position_m != b.balls[i].position_m) {
      return false;
    }
  }
  return a.game == b.game && a.player == b.player && a.in_hand == b.in_hand &&
         a.break_shot == b.break_shot && a.push_out_available == b.push_out_available &&
         a.consecutive_fouls == b.consecutive_fouls && a.groups == b.groups &&
         a.score == b.score && a.ball_on == b.ball_on && a.frame_over == b.frame_over &&
         a.winner == b.winner && a.shots == b.shots;
}

bool ShotFacts::cueBallPocketed() const { return pocketedBall(cue_ball) || offTable(cue_ball); }

bool ShotFacts::pocketedBall(const std::string& id) const {
  return std::any_of(pocketed.begin(), pocketed.end(),
                     [&](const PocketedBall& p) { return p.ball == id; });
}

bool ShotFacts::offTable(const std::string& id) const {
  return std::find(off_table.begin(), off_table.end(), id) != off_table.end();
}

std::vector<std::string> ShotFacts::objectBallsPocketed() const {
  std::vector<std::string> ids;
  for (const PocketedBall& p : pocketed) {
    if (p.ball != cue_ball) ids.push_back(p.ball);
  }
  return ids;
}

}  // namespace baize::engine
