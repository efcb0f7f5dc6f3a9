#include "tools/baize/stress_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/shot_simulator.h"
#include "tools/baize/cli_errors.h"

namespace baize::tools {
namespace {

using physics::BallState;

constexpr double kTableLength_m = 2.54;
constexpr double kTableWidth_m = 1.27;
// The strongest shot, m/s: above any cue strike (a break is about 10 m/s).
constexpr double kMaxSpeed_mps = 16.0;
// The most spin on each axis, in units of speed / R: beyond what a cue tip can give (about 2.5).
constexpr double kMaxSpinFactor = 3.0;
// Tiny shots: speeds log-uniform in this range, m/s, around the stopping thresholds' scale.
constexpr double kTinySpeedMin_mps = 1e-6;
constexpr double kTinySpeedMax_mps = 1e-3;
// Overlap between balls, or a centre closer than R to a cushion line, beyond this is a failure, m:
// contact positions come from polynomial roots, correct to rounding (~1e-14 m).
constexpr double kOverlapTolerance_m = 1e-9;
// Kinetic energy after an event may exceed that before by this fraction of it plus kEnergyFloor:
// rounding in the impact models (the exact cushion solver is accurate to 1e-9 of the speed, but
// conserves or loses energy by construction; the ball-ball model loses it exactly).
constexpr double kEnergyRelativeTolerance = 1e-12;
// Absolute floor for the energy check, J/kg: rounding of energies of balls near the stopping
// thresholds (speeds of 1e-9 m/s carry 5e-19 J/kg).
constexpr double kEnergyFloor_Jpkg = 1e-15;
// How many failing shots are printed in full.
constexpr int kMaxReportedShots = 10;

enum class SceneKind { Random, GapShot, FrozenLine, FrozenTriangle, CushionFrozen, Tiny, Grazing, Count };

const char* sceneKindName(SceneKind kind) {
  switch (kind) {
    case SceneKind::Random: return "random";
    case SceneKind::GapShot: return "gap shot";
    case SceneKind::FrozenLine: return "frozen line";
    case SceneKind::FrozenTriangle: return "frozen triangle";
    case SceneKind::CushionFrozen: return "ball against a cushion";
    case SceneKind::Tiny: return "tiny speed";
    case SceneKind::Grazing: return "grazing";
    case SceneKind::Count: break;
  }
  return "?";
}

struct StressFlags {
  long shots = 100000;
  std::uint64_t seed = 1;
  int max_balls = 6;
};

class SceneMaker {
 public:
  SceneMaker(std::uint64_t seed, double radius_m) : engine_(seed), R_(radius_m) {}

  double uniform(double lo, double hi) { return lo + (hi - lo) * ((engine_() >> 11) * 0x1.0p-53); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int integer(int lo, int hi) { return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1)); }
  Eigen::Vector2d direction() {
    const double a = uniform(0, 2 * M_PI);
    return {std::cos(a), std::sin(a)};
  }

  // Velocity `speed` along `dir` and spin up to kMaxSpinFactor * speed / R on each axis.
  void strike(BallState* b, const Eigen::Vector2d& dir, double speed) {
    b->velocity = {speed * dir.x(), speed * dir.y(), 0};
    const double w = kMaxSpinFactor * speed / R_;
    b->angular_velocity = {uniform(-w, w), uniform(-w, w), uniform(-w, w)};
  }

  bool clear(const std::vector<BallState>& balls, const Eigen::Vector2d& p) const {
    if (std::abs(p.x()) > kTableLength_m / 2 - R_ || std::abs(p.y()) > kTableWidth_m / 2 - R_) return false;
    for (const BallState& o : balls) {
      if ((o.position - p).norm() < 2 * R_) return false;
    }
    return true;
  }

  // Adds balls at random clear places until there are `count` (gives up quietly on a full table).
  void fill(std::vector<BallState>* balls, int count) {
    for (int attempt = 0; attempt < 1000 && static_cast<int>(balls->size()) < count; ++attempt) {
      const Eigen::Vector2d p(uniform(-kTableLength_m / 2 + R_, kTableLength_m / 2 - R_),
                              uniform(-kTableWidth_m / 2 + R_, kTableWidth_m / 2 - R_));
      if (clear(*balls, p)) {
        BallState b;
        b.position = p;
        balls->push_back(b);
      }
    }
  }

  // A cue ball `distance` back from `target` along -dir, aimed along dir; added if clear.
  bool addCue(std::vector<BallState>* balls, const Eigen::Vector2d& target, const Eigen::Vector2d& dir,
              double distance, double speed) {
    BallState cue;
    cue.position = target - distance * dir;
    if (!clear(*balls, cue.position)) return false;
    strike(&cue, dir, speed);
    balls->push_back(cue);
    return true;
  }

  std::vector<BallState> make(SceneKind kind, int max_balls) {
    std::vector<BallState> balls;
    const double speed = uniform(0, kMaxSpeed_mps);
    const Eigen::Vector2d centre(uniform(-0.8, 0.8), uniform(-0.3, 0.3));
    const Eigen::Vector2d dir = direction(), side(-dir.y(), dir.x());
    switch (kind) {
      case SceneKind::Random:
      case SceneKind::Count: {
        fill(&balls, integer(1, max_balls));
        strike(&balls[0], direction(), speed);
        break;
      }
      case SceneKind::GapShot: {  // at the gap between two touching balls: two contacts at once
        BallState a, b;
        a.position = centre + R_ * side;
        b.position = centre - R_ * side;
        balls = {a, b};
        addCue(&balls, centre, dir, uniform(0.1, 0.3), speed);
        break;
      }
      case SceneKind::FrozenLine: {  // a row of touching balls, the cue along or across it
        const int row = std::max(2, std::min(max_balls - 1, 4));
        for (int i = 0; i < row; ++i) {
          BallState b;
          b.position = centre + (2 * R_ * i) * dir;
          balls.push_back(b);
        }
        const Eigen::Vector2d aim = integer(0, 1) ? dir : Eigen::Vector2d((dir + uniform(-0.3, 0.3) * side).normalized());
        addCue(&balls, centre, aim, uniform(0.1, 0.3), speed);
        break;
      }
      case SceneKind::FrozenTriangle: {  // three mutually touching balls
        BallState a, b, c;
        a.position = centre;
        b.position = centre + 2 * R_ * dir;
        c.position = centre + 2 * R_ * (0.5 * dir + std::sqrt(0.75) * side);
        balls = {a, b, c};
        const Eigen::Vector2d aim = (dir + uniform(-0.2, 0.2) * side).normalized();
        addCue(&balls, centre, aim, uniform(0.1, 0.3), speed);
        fill(&balls, std::min(max_balls, static_cast<int>(balls.size()) + integer(0, 1)));
        break;
      }
      case SceneKind::CushionFrozen: {  // a ball touching cushion 0 (y = -W/2), hit or moving itself
        BallState a;
        a.position = {uniform(-1.0, 1.0), -kTableWidth_m / 2 + R_};
        balls = {a};
        if (integer(0, 1)) {
          strike(&balls[0], direction(), speed);
        } else {
          const Eigen::Vector2d aim = Eigen::Vector2d(uniform(-1, 1), -1).normalized();
          addCue(&balls, a.position, aim, uniform(0.1, 0.4), speed);
        }
        fill(&balls, std::min(max_balls, static_cast<int>(balls.size()) + integer(0, 2)));
        break;
      }
      case SceneKind::Tiny: {  // speeds near the stopping thresholds, often at a touching ball
        BallState a, b;
        a.position = centre;
        b.position = centre + 2 * R_ * dir;
        balls = {a, b};
        strike(&balls[0], integer(0, 1) ? dir : direction(), logUniform(kTinySpeedMin_mps, kTinySpeedMax_mps));
        fill(&balls, std::min(max_balls, 2 + integer(0, 1)));
        break;
      }
      case SceneKind::Grazing: {  // a straight pass at 2R + a tiny offset of either sign
        BallState a;
        a.position = centre;
        const double offset = (integer(0, 1) ? 1 : -1) * logUniform(1e-16, 1e-6) * (integer(0, 4) ? 1 : 0);
        balls = {a};
        BallState cue;
        cue.position = centre - uniform(0.1, 0.5) * dir - (2 * R_ + offset) * side;
        cue.velocity = {speed * dir.x(), speed * dir.y(), 0};
        const double follow = uniform(0, kMaxSpinFactor) * speed / R_;  // about the axis across the path
        cue.angular_velocity = {follow * side.x(), follow * side.y(), uniform(-kMaxSpinFactor, kMaxSpinFactor) * speed / R_};
        if (clear(balls, cue.position)) balls.push_back(cue);
        fill(&balls, std::min(max_balls, 2 + integer(0, 1)));
        break;
      }
    }
    return balls;
  }

 private:
  std::mt19937_64 engine_;
  double R_;
};

nlohmann::json sceneJson(const std::vector<BallState>& balls) {
  nlohmann::json list = nlohmann::json::array();
  for (const BallState& b : balls) {
    list.push_back({{"position", {b.position.x(), b.position.y()}},
                    {"velocity", {b.velocity.x(), b.velocity.y(), b.velocity.z()}},
                    {"angular_velocity", {b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z()}}});
  }
  return list;
}

bool finite(const BallState& b) {
  return b.position.allFinite() && b.velocity.allFinite() && b.angular_velocity.allFinite();
}

struct ShotCheck {
  std::map<std::string, long> failures;  // kind -> events failing that way within the shot
  std::string first_message;
  void fail(const std::string& kind, const std::string& message) {
    if (failures.empty()) first_message = kind + ": " + message;
    ++failures[kind];
  }
};

// Checks the balls at one instant: no overlap, none beyond a cushion, all finite.
void checkPositions(const engine::SimulationParams& p, const engine::TableGeometry& table,
                    const std::vector<BallState>& balls, double time_s, ShotCheck* check) {
  const double R = p.cushion.radius_m;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!finite(balls[i])) check->fail("non-finite", "ball " + std::to_string(i) + " at t = " + std::to_string(time_s));
    for (std::size_t j = 0; j < i; ++j) {
      const double gap = (balls[i].position - balls[j].position).norm() - 2 * R;
      if (gap < -kOverlapTolerance_m) {
        std::ostringstream m;
        m.precision(17);
        m << "balls " << j << " and " << i << " overlap by " << -gap << " m at t = " << time_s << " s";
        check->fail("overlap", m.str());
      }
    }
    for (std::size_t k = 0; k < table.cushions.size(); ++k) {
      const engine::CushionSegment& c = table.cushions[k];
      const Eigen::Vector2d along = c.end_m - c.start_m;
      const double s = (balls[i].position - c.start_m).dot(along) / along.squaredNorm();
      const double distance = c.inward_normal.dot(balls[i].position - c.start_m);
      if (s >= 0 && s <= 1 && distance < R - kOverlapTolerance_m) {
        std::ostringstream m;
        m.precision(17);
        m << "ball " << i << " is " << R - distance << " m beyond cushion " << k << " at t = " << time_s << " s";
        check->fail("escape", m.str());
      }
    }
  }
}

struct ShotOutcome {
  ShotCheck check;
  long events = 0;
  double worst_energy_growth = 0;  // largest relative growth across an event
};

ShotOutcome runShot(const engine::SimulationParams& p, const engine::TableGeometry& table,
                    const std::vector<BallState>& input) {
  ShotOutcome out;
  ShotCheck& check = out.check;
  engine::SimulationResult result;
  try {
    result = engine::simulate(p, table, input);
  } catch (const std::runtime_error& e) {
    check.fail("hang", e.what());
    return out;
  } catch (const std::invalid_argument& e) {
    check.fail("rejected", e.what());
    return out;
  }
  out.events = static_cast<long>(result.events.size());
  const int n = static_cast<int>(input.size());
  std::vector<BallState> known = input;  // each ball's last known state and its time
  std::vector<double> known_time(n, 0);
  std::vector<bool> pocketed(n, false);
  for (const engine::Event& e : result.events) {
    if (!std::isfinite(e.time_s)) check.fail("non-finite", "an event time");
    std::vector<BallState> now(n);
    for (int i = 0; i < n; ++i) now[i] = physics::advance(p.cloth, known[i], std::max(0.0, e.time_s - known_time[i]));
    double before = 0, after = 0;
    for (const BallState& b : e.before) before += physics::specificKineticEnergy(p.cloth, b);
    for (const BallState& b : e.after) {
      if (!finite(b)) check.fail("non-finite", std::string("state after a ") + engine::eventKindName(e.kind));
      after += physics::specificKineticEnergy(p.cloth, b);
    }
    if (before > 0) out.worst_energy_growth = std::max(out.worst_energy_growth, (after - before) / before);
    if (!(after <= before * (1 + kEnergyRelativeTolerance) + kEnergyFloor_Jpkg)) {
      std::ostringstream m;
      m.precision(17);
      m << engine::eventKindName(e.kind) << " at t = " << e.time_s << " s: " << before << " -> " << after << " J/kg";
      check.fail("energy", m.str());
    }
    now[e.ball] = e.after[0];
    if (e.kind == engine::EventKind::BallBall) now[e.other] = e.after[1];
    if (e.kind == engine::EventKind::Pocket) pocketed[e.ball] = true;
    std::vector<BallState> on_table;
    for (int i = 0; i < n; ++i) {
      known[i] = now[i];
      known_time[i] = e.time_s;
      if (!pocketed[i]) on_table.push_back(now[i]);
    }
    checkPositions(p, table, on_table, e.time_s, &check);
  }
  std::vector<BallState> final_on_table;
  for (const engine::BallRecord& b : result.final_balls) {
    if (!b.pocketed) final_on_table.push_back(b.state);
  }
  checkPositions(p, table, final_on_table, result.end_time_s, &check);
  return out;
}

void runStress(const StressFlags& flags) {
  if (flags.shots < 1) rejectFlag("--shots", static_cast<double>(flags.shots), "it must be >= 1");
  if (flags.max_balls < 2 || flags.max_balls > 16) {
    rejectFlag("--balls", flags.max_balls, "it must lie in [2, 16] (the most balls per shot)");
  }
  const engine::SimulationParams params = engine::poolSimulationParams();
  const engine::TableGeometry table = engine::rectangularTable(kTableLength_m, kTableWidth_m);
  const double R = params.cushion.radius_m;

  std::map<std::string, long> failures_by_kind;  // kind -> shots failing that way
  long events = 0, failed_shots = 0;
  double worst_energy_growth = 0;
  const auto started = std::chrono::steady_clock::now();
  for (long shot = 0; shot < flags.shots; ++shot) {
    // Each shot has its own generator, so a shot can be made again from (seed, shot) alone.
    SceneMaker maker(flags.seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(shot), R);
    const SceneKind kind = static_cast<SceneKind>(shot % static_cast<long>(SceneKind::Count));
    const std::vector<BallState> balls = maker.make(kind, flags.max_balls);
    const ShotOutcome outcome = runShot(params, table, balls);
    events += outcome.events;
    worst_energy_growth = std::max(worst_energy_growth, outcome.worst_energy_growth);
    if (outcome.check.failures.empty()) continue;
    ++failed_shots;
    for (const auto& entry : outcome.check.failures) ++failures_by_kind[entry.first];  // shots, not events
    if (failed_shots <= kMaxReportedShots) {
      nlohmann::json repro = {{"seed", flags.seed}, {"shot", shot}, {"scene", sceneKindName(kind)},
                              {"first_failure", outcome.check.first_message},
                              {"table_m", {kTableLength_m, kTableWidth_m}}, {"balls", sceneJson(balls)}};
      std::cout << "FAILED SHOT " << repro.dump() << '\n';
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << "stress: shots " << flags.shots << ", events " << events << ", failed shots " << failed_shots
            << ", failed shots by kind";
  if (failures_by_kind.empty()) std::cout << " none";
  for (const auto& [what, count] : failures_by_kind) std::cout << ' ' << what << '=' << count;
  std::cout.precision(3);
  std::cout << ", largest energy growth " << worst_energy_growth << " (relative), " << seconds << " s, "
            << flags.shots / seconds << " shots/s\n";
  if (failed_shots > 0) throw std::runtime_error(std::to_string(failed_shots) + " shots failed their checks");
}

}  // namespace

void addStressCommand(CLI::App& parent) {
  auto flags = std::make_shared<StressFlags>();
  CLI::App* command = parent.add_subcommand(
      "stress",
      "Run many seeded random shots through the event loop and check every event (finite values, no "
      "overlap, no ball beyond a cushion, energy never growing, every shot coming to rest)");
  command->add_option("--shots", flags->shots, "number of shots")->capture_default_str();
  command->add_option("--seed", flags->seed, "random seed (shot k uses a generator seeded from it and k)")
      ->capture_default_str();
  command->add_option("--balls", flags->max_balls, "most balls in a shot")->capture_default_str();
  command->callback([flags] {
    if (const int status = runReportingErrors("stress", [&] { runStress(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
