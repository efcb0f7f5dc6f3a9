// A game's state between shots and the rulings on a shot, as plain data (docs/games.md): the balls
// on the table, whose turn it is, the cue ball in hand, fouls in a row, the push-out, the groups of
// 8-ball, the score and the ball on of snooker, the end of the frame. The rules of each game
// (rotation_rules, eight_ball_rules, snooker_rules) map a state and a shot's facts to the next
// state and a decision; they simulate nothing.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/rack.h"
#include "engine/io/result_file.h"

namespace baize::engine {

enum class Game { NineBall, TenBall, EightBall, Snooker };

// "9-ball", "10-ball", "8-ball", "snooker".
const char* gameName(Game game);
std::vector<std::string> gameNames();
std::optional<Game> gameNamed(const std::string& name);

// Where the player may place the cue ball before the shot.
enum class CueBallInHand {
  No,                // played from where it lies
  BehindHeadString,  // pool: x <= the head string (the break)
  Anywhere,          // pool: after a standard foul
  InD,               // snooker: in the D (the break-off, after an in-off)
};
const char* inHandName(CueBallInHand in_hand);

// 8-ball groups; None while the table is open.
enum class Group { None, Solids, Stripes };
const char* groupName(Group group);

struct GameState {
  Game game = Game::NineBall;
  std::vector<PlacedBall> balls;  // on the table, the cue ball first (in hand: where it was)
  int player = 0;                 // 0 or 1: who plays the next shot
  CueBallInHand in_hand = CueBallInHand::No;
  bool break_shot = true;
  bool push_out_available = false;               // 9- and 10-ball: the shot after a legal break
  std::array<int, 2> consecutive_fouls{{0, 0}};  // per player, without a legal shot between
  std::array<Group, 2> groups{{Group::None, Group::None}};
  std::array<int, 2> score{{0, 0}};  // snooker points
  std::string ball_on;               // snooker: "red", "colour" (after a red) or a colour's id
  bool frame_over = false;
  int winner = -1;  // 0 or 1 once the frame is over (-1: not decided)
  int shots = 0;    // shots played

  const PlacedBall* ball(const std::string& id) const;  // nullptr when not on the table
  bool onTable(const std::string& id) const { return ball(id) != nullptr; }
};

bool operator==(const GameState& a, const GameState& b);

// What the player announces before the shot: the ball called (8-ball, 10-ball) or nominated
// (snooker, a colour after a red) and its pocket; a push-out (9- and 10-ball).
struct ShotCall {
  std::string ball;  // empty: nothing called
  int pocket = -1;   // index into Table::pockets; -1: none
  bool push_out = false;
};

// A shot's facts as a referee sees them, read from its events (shot_facts.h).
struct ShotFacts {
  std::string cue_ball = "cue";
  std::optional<std::string> first_hit;  // the first ball the cue ball touched
  std::vector<PocketedBall> pocketed;    // in the order they fell, the cue ball included
  // Some ball (cue or object) touched a cushion or jaw after the cue ball's first contact.
  bool cushion_after_first_hit = false;
  std::vector<std::string> object_balls_to_cushion;  // distinct object balls that touched one
  // Balls that left the table. The simulator refuses such a shot (BallLeftTableError), so only
  // hand-made facts have any; the rules still rule on them.
  std::vector<std::string> off_table;
  std::vector<PlacedBall> final_balls;  // the balls left on the table, where they stopped

  bool cueBallPocketed() const;
  bool pocketedBall(const std::string& id) const;
  bool offTable(const std::string& id) const;
  std::vector<std::string> objectBallsPocketed() const;  // in order, the cue ball left out
};

enum class GameFoul {
  None,
  CueBallPocketed,        // or off the table
  NoBallHit,              // the cue ball touched no ball
  WrongBallFirst,         // the first ball hit was not a legal one (snooker: not on)
  NoCushionAfterContact,  // pool: nothing pocketed and no ball to a cushion after the contact
  BallOffTable,           // an object ball left the table
  BallNotOnPotted,        // snooker: a ball not on was potted
  IllegalBreak,           // pool: no ball pocketed and fewer than four object balls to a cushion
};
const char* gameFoulName(GameFoul foul);

struct Decision {
  GameFoul foul = GameFoul::None;
  std::string rule;   // the rules each ruling rests on, e.g. "WPA 6.2; WPA 2.5"
  bool turn_passes = false;
  bool frame_over = false;
  int winner = -1;
  std::vector<std::string> respotted;  // balls put back on the table, in the order placed
  int points = 0;   // snooker: scored by the striker
  int penalty = 0;  // snooker: given to the opponent
};

struct Ruling {
  GameState next;
  Decision decision;
};

}  // namespace baize::engine
