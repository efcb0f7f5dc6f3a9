#include "render/shot_picture.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include "physics/value_text.h"
#include "render/table_picture.h"

namespace baize::render {
namespace {

// Traces lie a hair above the cloth and markings (m), markers above the traces; only the angled
// view's perspective could show the difference, and there it is far below a pixel.
constexpr double kTraceHeight_m = 0.0;
// Samples per trace piece are capped (a shot is at most a few tens of metres long; at 1 mm a
// pixel this is far more than needed).
constexpr long kMaxSamplesPerPiece = 200000;

struct Run {
  bool sliding = false;
  std::vector<Eigen::Vector2d> points;
};

// The piece of `trajectory` in effect at t (the last starting at or before t).
const engine::TrajectoryPiece& pieceAt(const engine::Trajectory& trajectory, double t_s) {
  auto piece = std::upper_bound(
      trajectory.begin(), trajectory.end(), t_s,
      [](double t, const engine::TrajectoryPiece& q) { return t < q.start_time_s; });
  return piece == trajectory.begin() ? *piece : *(piece - 1);
}

void addPoint(bool sliding, const Eigen::Vector2d& p, std::vector<Run>& runs) {
  if (runs.empty() || runs.back().sliding != sliding) {
    Run run{sliding, {}};
    if (!runs.empty()) run.points.push_back(runs.back().points.back());  // joined, no gap
    runs.push_back(run);
  }
  if (runs.back().points.empty() || (runs.back().points.back() - p).norm() > 0) {
    runs.back().points.push_back(p);
  }
}

// The ball's path up to `until_s` in runs of one style (sliding or not).
std::vector<Run> traceRuns(const physics::ClothParams& cloth, const engine::Trajectory& trajectory,
                           double until_s, double step_m) {
  std::vector<Run> runs;
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    const engine::TrajectoryPiece& piece = trajectory[k];
    if (piece.pocketed || piece.start_time_s >= until_s) break;
    const double piece_end =
        k + 1 < trajectory.size() ? std::min(trajectory[k + 1].start_time_s, until_s) : until_s;
    physics::BallState state = piece.state;
    double t = piece.start_time_s;
    // Within a piece the ball may pass through several motion states (sliding, rolling, ...).
    while (t < piece_end) {
      const physics::MotionState motion = physics::motionState(cloth, state);
      if (motion == physics::MotionState::Spinning || motion == physics::MotionState::Stationary) {
        break;  // the centre stays put from here on
      }
      const double end = std::min(piece_end, t + physics::timeToStateChange(cloth, state));
      const physics::BallState at_end = physics::advance(cloth, state, end - t);
      // |v| is linear in time within one state, so the larger end speed bounds it.
      const double speed_bound = std::max(state.velocity.norm(), at_end.velocity.norm());
      const long samples = std::clamp(
          static_cast<long>(std::ceil(speed_bound * (end - t) / step_m)), 1L, kMaxSamplesPerPiece);
      const bool sliding = motion == physics::MotionState::Sliding;
      for (long i = 0; i <= samples; ++i) {
        const double ti = i == samples ? end : t + (end - t) * static_cast<double>(i) / samples;
        addPoint(sliding, engine::sampleTrajectory(cloth, trajectory, ti).position, runs);
      }
      state = at_end;
      t = end;
    }
  }
  return runs;
}

// Cuts a polyline into dashes along its length.
std::vector<std::vector<Eigen::Vector2d>> dashes(const std::vector<Eigen::Vector2d>& points,
                                                 double on_m, double off_m) {
  std::vector<std::vector<Eigen::Vector2d>> out;
  double phase = 0;  // distance into the current on+off period
  bool drawing = true;
  std::vector<Eigen::Vector2d> current{points.front()};
  for (std::size_t i = 1; i < points.size(); ++i) {
    Eigen::Vector2d from = points[i - 1];
    double left = (points[i] - from).norm();
    const Eigen::Vector2d direction = (points[i] - from) / std::max(left, 1e-300);
    while (left > 0) {
      const double limit = drawing ? on_m : off_m;
      const double take = std::min(left, limit - phase);
      from += direction * take;
      left -= take;
      phase += take;
      if (drawing) current.push_back(from);
      if (phase >= limit) {
        phase = 0;
        if (drawing && current.size() > 1) out.push_back(current);
        drawing = !drawing;
        current = {from};
      }
    }
  }
  if (drawing && current.size() > 1) out.push_back(current);
  return out;
}

Disc flatDisc(const Eigen::Vector2d& centre, double radius, const Rgba& colour, DiscStyle style,
              double inner_fraction = 0) {
  return Disc{
      Eigen::Vector3d(centre.x(), centre.y(), 0), radius, colour, style, inner_fraction, {}};
}

}  // namespace

Rgba ballBallMarkerColour() { return colourFromHex("#151515"); }
Rgba cushionMarkerColour() { return colourFromHex("#ff9900"); }
Rgba pocketMarkerColour() { return colourFromHex("#ff2a2a"); }

Rgba ballColour(const engine::BallSet& set, const std::string& id) {
  return colourFromHex(set.ball(id).colour);
}

double pixelSizeFor(const engine::Table& table, int width_px, int height_px) {
  const double outer_length_m = table.length_m + 2 * kRailOuterEdge_m;
  const double outer_width_m = table.width_m + 2 * kRailOuterEdge_m;
  return std::max(outer_length_m / std::max(width_px, 1), outer_width_m / std::max(height_px, 1));
}

double firstSpeed(const engine::Trajectory& trajectory) {
  for (const engine::TrajectoryPiece& piece : trajectory) {
    if (piece.pocketed) break;
    const double speed = piece.state.velocity.head<2>().norm();
    if (speed > physics::kSpeedEpsilon_mps) return speed;
  }
  return 0;
}

std::optional<std::string> legendText(const std::string& id, const engine::Trajectory& trajectory) {
  for (const engine::TrajectoryPiece& piece : trajectory) {
    if (piece.pocketed) break;
    const Eigen::Vector3d& v = piece.state.velocity;
    const double speed = v.head<2>().norm();
    if (speed <= physics::kSpeedEpsilon_mps) continue;
    const Eigen::Vector3d across(-v.y() / speed, v.x() / speed, 0);  // z x (v / |v|)
    std::ostringstream text;
    // Spins are rounded to whole rad/s first, and + 0.0 turns -0 into 0.
    text << std::fixed << id << ": " << std::setprecision(2) << speed << " m/s, roll "
         << std::setprecision(0) << std::round(piece.state.angular_velocity.dot(across)) + 0.0
         << " rad/s, side " << std::round(piece.state.angular_velocity.z()) + 0.0 << " rad/s";
    return text.str();
  }
  return std::nullopt;
}

Picture buildShotPicture(const ShotRecord& shot, const PictureOptions& options) {
  if (!(options.time_s >= 0)) {
    throw std::invalid_argument("picture time " + physics::valueText(options.time_s) +
                                " s is not allowed: it must be >= 0 (infinity: the end)");
  }
  if (!(options.pixel_size_m > 0) || !std::isfinite(options.pixel_size_m)) {
    throw std::invalid_argument("pixel size " + physics::valueText(options.pixel_size_m) +
                                " m is not allowed: it must be finite and > 0");
  }
  if (shot.trajectories.size() != shot.ball_ids.size()) {
    throw std::invalid_argument("shot with " + std::to_string(shot.ball_ids.size()) +
                                " balls and " + std::to_string(shot.trajectories.size()) +
                                " trajectories cannot be drawn: it needs one per ball");
  }
  for (const engine::Trajectory& trajectory : shot.trajectories) {
    if (trajectory.empty()) throw std::invalid_argument("a ball of the shot has no trajectory");
  }
  Picture picture;
  addTable(shot.table, picture);
  const double px = options.pixel_size_m;
  const double t_end = std::min(options.time_s, shot.end_time_s);
  const double radius_m = shot.ball_set.radius_m;

  if (options.traces) {
    for (std::size_t i = 0; i < shot.trajectories.size(); ++i) {
      const engine::BallSpec& spec = shot.ball_set.ball(shot.ball_ids[i]);
      const Rgba colour = colourFromHex(spec.colour);
      const Eigen::Vector2d start = shot.trajectories[i].front().state.position;
      const engine::TrajectoryPiece& now = pieceAt(shot.trajectories[i], t_end);
      const Eigen::Vector2d here =
          engine::sampleTrajectory(shot.cloth, shot.trajectories[i], t_end).position;
      if (!now.pocketed && (here - start).norm() < kMovedDistance_m) continue;
      picture.items.push_back(flatDisc(start, radius_m, colour, DiscStyle::Ring, 0.85));
      for (const Run& run :
           traceRuns(shot.cloth, shot.trajectories[i], t_end, kTraceStep_px * px)) {
        if (run.points.size() < 2) continue;
        std::vector<std::vector<Eigen::Vector2d>> parts;
        if (run.sliding) {
          parts = dashes(run.points, kDashOn_px * px, kDashOff_px * px);
        } else {
          parts = {run.points};
        }
        for (const auto& part : parts) {
          // Built in place: GCC 12 warns falsely about a moved-from temporary otherwise.
          Stroke& trace = std::get<Stroke>(picture.items.emplace_back(Stroke{}));
          trace.points_m = part;
          trace.width_m = kTraceWidth_px * px;
          trace.z_m = kTraceHeight_m;
          trace.colour = colour;
          if (spec.stripe) {
            Stroke& core = std::get<Stroke>(picture.items.emplace_back(Stroke{}));
            core.points_m = part;
            core.width_m = kStripeCoreWidth_px * px;
            core.z_m = kTraceHeight_m;
            core.colour = colourFromHex("#ffffff");
          }
        }
      }
    }
    for (const engine::Event& e : shot.events) {
      if (e.time_s > t_end) break;
      const auto at = [&](int ball) {
        return engine::sampleTrajectory(shot.cloth, shot.trajectories.at(ball), e.time_s).position;
      };
      switch (e.kind) {
        case engine::EventKind::BallBall:
          picture.items.push_back(flatDisc(0.5 * (at(e.ball) + at(e.other)),
                                           kBallBallMarkerRadius_px * px, ballBallMarkerColour(),
                                           DiscStyle::Ring, 0.5));
          break;
        case engine::EventKind::Cushion:
        case engine::EventKind::Jaw:
          picture.items.push_back(flatDisc(at(e.ball), kCushionMarkerRadius_px * px,
                                           cushionMarkerColour(), DiscStyle::Flat));
          break;
        case engine::EventKind::Pocket:
          picture.items.push_back(flatDisc(at(e.ball), kPocketMarkerRadius_px * px,
                                           pocketMarkerColour(), DiscStyle::Ring, 0.55));
          break;
        case engine::EventKind::StateChange:
          break;
      }
    }
  }

  for (std::size_t i = 0; i < shot.trajectories.size(); ++i) {
    if (pieceAt(shot.trajectories[i], t_end).pocketed) continue;
    const engine::BallSpec& spec = shot.ball_set.ball(shot.ball_ids[i]);
    const Eigen::Vector2d p =
        engine::sampleTrajectory(shot.cloth, shot.trajectories[i], t_end).position;
    picture.items.push_back(Disc{Eigen::Vector3d(p.x(), p.y(), radius_m), radius_m,
                                 colourFromHex(spec.colour),
                                 spec.stripe ? DiscStyle::StripedBall : DiscStyle::Ball, 0,
                                 spec.number > 0 ? std::to_string(spec.number) : std::string()});
  }
  if (options.legend) {
    int nudged = 0;
    for (std::size_t i = 0; i < shot.trajectories.size(); ++i) {
      const std::optional<std::string> text = legendText(shot.ball_ids[i], shot.trajectories[i]);
      if (!text) continue;
      if (firstSpeed(shot.trajectories[i]) < kLegendMinSpeed_mps) {
        ++nudged;
        continue;
      }
      const engine::BallSpec& spec = shot.ball_set.ball(shot.ball_ids[i]);
      picture.legend.push_back(LegendRow{true, colourFromHex(spec.colour), spec.stripe, *text});
    }
    if (nudged > 0) {
      picture.legend.push_back(LegendRow{false,
                                         {},
                                         false,
                                         std::to_string(nudged) + " more " +
                                             (nudged == 1 ? "ball" : "balls") +
                                             " nudged (first speed under 0.05 m/s)"});
    }
    picture.legend.push_back(LegendRow{false, {}, false, "solid: rolling, dashed: sliding"});
    picture.legend.push_back(
        LegendRow{false, {}, false, "dark ring: ball-ball, orange: cushion, red ring: pocket"});
  }
  return picture;
}

}  // namespace baize::render
