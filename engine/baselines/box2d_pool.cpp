#include "engine/baselines/box2d_pool.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "physics/value_text.h"

namespace baize::engine {
namespace {

using engine::EventKind;
using physics::BallState;

// The smallest length unit, m: Box2D's 5 mm slop becomes 0.05 mm, far below anything visible at
// ball size, while float positions on a 3.6 m table still resolve 0.2 um.
constexpr double kMinLengthUnit_m = 0.01;
// The fastest ball the unit must carry without Box2D's travel clamp (b2_maxTranslation units per
// step), m/s: the extreme cue speed of physics-notes section 4.
constexpr double kFastestBall_mps = 16.0;
// Contacts slower than this bounce (Box2D's restitutionThreshold), m/s: the slowest approach
// speeds that matter at the table are about 1 cm/s.
constexpr double kRestitutionThreshold_mps = 1e-3;
// A ball moving more than this share of its radius per step is a bullet: tunnelling through
// another ball needs a travel of about 2R, so this leaves a wide margin.
constexpr double kBulletTravelPerRadius = 0.25;
// Jaw arcs are split into edges no longer than this angle, rad: the chord then sags at most
// rho (1 - cos 2.5 deg) < 1e-3 rho, a few hundredths of a mm on pool jaws.
constexpr double kJawEdgeAngle_rad = 5.0 * M_PI / 180;
// Jaw edges are at least this many Box2D linear slops long (Box2D asserts edges above one slop).
constexpr double kShortestEdgeSlops = 2.0;
// Ends of cushion pieces closer than this join into one chain, m: the table builder makes them
// meet to rounding.
constexpr double kJoinTolerance_m = 1e-6;
// Head-on speed for calibrating the cushion restitution, m/s: within the range where the Mathavan
// 2010 model is linear in speed (any speed gives the same ratio).
constexpr double kCalibrationSpeed_mps = 1.0;
// Slip speed in Alciatore's fit at which the constant ball-ball friction is taken, m/s: a typical
// cut shot between 0.5 and 2 m/s.
constexpr double kBallFrictionSlip_mps = 1.0;

// What a piece of the Box2D boundary stands for: cushion or jaw `index` of the table.
struct EdgeTag {
  EventKind kind = EventKind::Cushion;
  int index = 0;
};

// Fixture user data: balls carry their index + 1; each chain points at its per-edge tags.
struct ChainTags {
  std::vector<EdgeTag> edges;
};

struct Polyline {
  std::vector<Eigen::Vector2d> points;
  std::vector<EdgeTag> tags;  // one per edge
};

Eigen::Vector2d tagInwardNormal(const engine::TableGeometry& table, const EdgeTag& tag,
                                const Eigen::Vector2d& at) {
  if (tag.kind == EventKind::Cushion) return table.cushions[tag.index].inward_normal;
  return (at - table.jaws[tag.index].centre_m).normalized();
}

// The table's cushion segments and jaw arcs joined end to end into chains, each oriented so the
// table lies to the right of its edges (Box2D chains collide on that side only). skin_m is how far
// the chains will be set back; the jaws' edges are kept longer than shortest_edge_m there (Box2D
// refuses chain edges shorter than its linear slop).
std::vector<Polyline> boundaryChains(const engine::TableGeometry& table, double skin_m,
                                     double shortest_edge_m) {
  std::vector<Polyline> pieces;
  for (int k = 0; k < static_cast<int>(table.cushions.size()); ++k) {
    pieces.push_back(
        {{table.cushions[k].start_m, table.cushions[k].end_m}, {{EventKind::Cushion, k}}});
  }
  for (int k = 0; k < static_cast<int>(table.jaws.size()); ++k) {
    const engine::JawArc& jaw = table.jaws[k];
    const double span = jaw.end_angle_rad - jaw.start_angle_rad;
    const double set_back_length_m = span * std::max(0.0, jaw.radius_m - skin_m);
    const int edges = std::max(1, std::min(static_cast<int>(std::ceil(span / kJawEdgeAngle_rad)),
                                           static_cast<int>(set_back_length_m / shortest_edge_m)));
    Polyline arc;
    for (int e = 0; e <= edges; ++e)
      arc.points.push_back(jaw.pointAt(jaw.start_angle_rad + span * e / edges));
    arc.tags.assign(edges, {EventKind::Jaw, k});
    pieces.push_back(arc);
  }
  auto reversed = [](Polyline p) {
    std::reverse(p.points.begin(), p.points.end());
    std::reverse(p.tags.begin(), p.tags.end());
    return p;
  };
  auto near = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - b).norm() < kJoinTolerance_m;
  };
  std::vector<char> used(pieces.size(), 0);
  std::vector<Polyline> chains;
  for (std::size_t seed = 0; seed < pieces.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = 1;
    Polyline chain = pieces[seed];
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t k = 0; k < pieces.size() && !grew; ++k) {
        if (used[k]) continue;
        Polyline piece = pieces[k];
        if (near(piece.points.back(), chain.points.back())) piece = reversed(piece);
        if (near(piece.points.front(), chain.points.back())) {
          chain.points.insert(chain.points.end(), piece.points.begin() + 1, piece.points.end());
          chain.tags.insert(chain.tags.end(), piece.tags.begin(), piece.tags.end());
          used[k] = grew = 1;
          continue;
        }
        if (near(piece.points.front(), chain.points.front())) piece = reversed(piece);
        if (near(piece.points.back(), chain.points.front())) {
          chain.points.insert(chain.points.begin(), piece.points.begin(), piece.points.end() - 1);
          chain.tags.insert(chain.tags.begin(), piece.tags.begin(), piece.tags.end());
          used[k] = grew = 1;
        }
      }
    }
    // The right of edge direction d is (d.y, -d.x); it must point to the table.
    const Eigen::Vector2d d = chain.points[1] - chain.points[0];
    const Eigen::Vector2d mid = 0.5 * (chain.points[0] + chain.points[1]);
    if (Eigen::Vector2d(d.y(), -d.x()).dot(tagInwardNormal(table, chain.tags[0], mid)) < 0)
      chain = reversed(chain);
    chains.push_back(chain);
  }
  return chains;
}

// The chain moved away from the table by `skin` (m): each vertex goes to where its neighbouring
// edges, each shifted along its own normal, meet (a plain shift at the chain's ends).
std::vector<Eigen::Vector2d> setBack(const Polyline& chain, bool closed, double skin) {
  const std::size_t n = chain.points.size();
  auto outward = [&](std::size_t e) {  // left of edge e: away from the table
    const Eigen::Vector2d d = (chain.points[(e + 1) % n] - chain.points[e]).normalized();
    return Eigen::Vector2d(-d.y(), d.x());
  };
  const std::size_t edges = closed ? n : n - 1;
  std::vector<Eigen::Vector2d> out(n);
  for (std::size_t v = 0; v < n; ++v) {
    const bool has_before = closed || v > 0, has_after = closed || v + 1 < n;
    const Eigen::Vector2d before = has_before ? outward((v + edges - 1) % edges) : outward(v);
    const Eigen::Vector2d after = has_after ? outward(v % edges) : before;
    out[v] = chain.points[v] + skin * (before + after) / (1 + before.dot(after));
  }
  return out;
}

struct Ball {
  b2Body* body = nullptr;                                           // null once pocketed
  Eigen::Vector2d horizontal_spin_radps = Eigen::Vector2d::Zero();  // w_x, w_y, beside Box2D
};

// Records contacts that begin while approaching and sets each contact's material.
class ContactRecorder : public b2ContactListener {
 public:
  ContactRecorder(double cushion_restitution, double cushion_friction, double ball_restitution,
                  double ball_friction, double restitution_threshold_units)
      : cushion_restitution_(cushion_restitution),
        cushion_friction_(cushion_friction),
        ball_restitution_(ball_restitution),
        ball_friction_(ball_friction),
        threshold_(restitution_threshold_units) {}

  double now_s = 0;
  std::vector<engine::Event>* events = nullptr;
  std::vector<Ball>* balls = nullptr;
  double unit_m = 1;  // metres per Box2D unit
  // Horizontal spin change per unit of horizontal impulse at the cushion nose, 1/(kg m):
  // R sin(theta) / I (see PostSolve).
  double nose_spin_per_impulse = 0;

  void BeginContact(b2Contact* contact) override {
    b2Fixture* a = contact->GetFixtureA();
    b2Fixture* b = contact->GetFixtureB();
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    const b2Vec2 relative = b->GetBody()->GetLinearVelocity() - a->GetBody()->GetLinearVelocity();
    if (!(b2Dot(relative, manifold.normal) < 0)) return;  // not approaching (normal: A to B)
    engine::Event event;
    event.time_s = now_s;
    const int ball_a = ballIndex(a), ball_b = ballIndex(b);
    if (ball_a >= 0 && ball_b >= 0) {
      event.kind = EventKind::BallBall;
      event.ball = std::min(ball_a, ball_b);
      event.other = std::max(ball_a, ball_b);
    } else {
      const bool a_is_ball = ball_a >= 0;
      b2Fixture* edge = a_is_ball ? b : a;
      const int child = a_is_ball ? contact->GetChildIndexB() : contact->GetChildIndexA();
      const EdgeTag& tag =
          reinterpret_cast<const ChainTags*>(edge->GetUserData().pointer)->edges.at(child);
      event.kind = tag.kind;
      event.ball = a_is_ball ? ball_a : ball_b;
      event.index = tag.index;
    }
    events->push_back(event);
  }

  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    const bool both_balls =
        ballIndex(contact->GetFixtureA()) >= 0 && ballIndex(contact->GetFixtureB()) >= 0;
    contact->SetRestitution(
        static_cast<float>(both_balls ? ball_restitution_ : cushion_restitution_));
    contact->SetFriction(static_cast<float>(both_balls ? ball_friction_ : cushion_friction_));
    contact->SetRestitutionThreshold(static_cast<float>(threshold_));
  }

  // Box2D resolves a cushion contact at the ball's equator; the real nose touches the ball at
  // r = R (cos(theta) d + sin(theta) z), d the horizontal direction to the cushion. The horizontal
  // impulse P that Box2D applied there turns the spin about the horizontal axes by
  // r x P / I = R sin(theta) (z x P) / I (the vertical part, about z, Box2D applies itself), which
  // is how the cushion takes topspin off a ball. That uses only Box2D's own impulses.
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override {
    const int ball_a = ballIndex(contact->GetFixtureA()),
              ball_b = ballIndex(contact->GetFixtureB());
    if ((ball_a >= 0) == (ball_b >= 0)) return;  // ball-ball (at the equator) or nothing
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    const Eigen::Vector2d n(manifold.normal.x, manifold.normal.y);  // from A to B
    const Eigen::Vector2d t(n.y(), -n.x());                         // Box2D's tangent
    double normal = 0, tangent = 0;
    for (int k = 0; k < impulse->count; ++k) {
      normal += impulse->normalImpulses[k];
      tangent += impulse->tangentImpulses[k];
    }
    // Impulse on B along (n, t); on A the opposite. In N s: Box2D impulses are kg unit/s.
    const double sign = ball_b >= 0 ? 1.0 : -1.0;
    const Eigen::Vector2d P = sign * unit_m * (normal * n + tangent * t);
    Ball& ball = (*balls)[ball_b >= 0 ? ball_b : ball_a];
    ball.horizontal_spin_radps += nose_spin_per_impulse * Eigen::Vector2d(-P.y(), P.x());
  }

  static int ballIndex(b2Fixture* f) {
    return f->GetBody()->GetType() == b2_dynamicBody
               ? static_cast<int>(f->GetBody()->GetUserData().pointer) - 1
               : -1;
  }

 private:
  double cushion_restitution_, cushion_friction_, ball_restitution_, ball_friction_, threshold_;
};

void validate(const engine::SimulationParams& p, const engine::TableGeometry& table,
              const std::vector<BallState>& balls, const Box2dPoolSettings& s) {
  if (!(s.time_step_s >= kMinBox2dTimeStep_s && s.time_step_s <= kMaxBox2dTimeStep_s)) {
    physics::rejectValue("Box2D time step (s)", s.time_step_s,
                         "it must lie in [" + physics::valueText(kMinBox2dTimeStep_s) + ", " +
                             physics::valueText(kMaxBox2dTimeStep_s) + "]");
  }
  if (!(s.stop_after_s > 0))
    physics::rejectValue("Box2D stop time (s)", s.stop_after_s, "it must be > 0");
  if (s.velocity_iterations < 1 || s.position_iterations < 1) {
    physics::rejectValue("Box2D velocity or position iterations",
                         std::min(s.velocity_iterations, s.position_iterations),
                         "both must be >= 1");
  }
  engine::validateSimulationInput(p, table, balls);
}

}  // namespace

double box2dLengthUnit_m(double time_step_s) {
  return std::max(kMinLengthUnit_m, kFastestBall_mps * time_step_s / b2_maxTranslation);
}

double calibratedCushionRestitution(const engine::SimulationParams& params) {
  physics::BallVelocity rolling;  // cushion frame: y into the cushion, natural roll about x
  rolling.v = {0, kCalibrationSpeed_mps, 0};
  rolling.w = {kCalibrationSpeed_mps / params.ball.radius_m, 0, 0};
  return -params.cushion->resolve(params, rolling).v.y() / kCalibrationSpeed_mps;
}

engine::SimulationResult simulateBox2d(const engine::SimulationParams& p,
                                       const engine::TableGeometry& table,
                                       const std::vector<BallState>& input,
                                       const Box2dPoolSettings& settings) {
  validate(p, table, input, settings);
  const double dt = settings.time_step_s;
  const double unit_m = box2dLengthUnit_m(dt);
  auto toBox = [&](const Eigen::Vector2d& q) {
    return b2Vec2(static_cast<float>(q.x() / unit_m), static_cast<float>(q.y() / unit_m));
  };
  const double R = p.ball.radius_m, mass = p.ball.mass_kg;

  b2World world(b2Vec2(0, 0));  // seen from above: gravity acts through the cloth model
  world.SetAllowSleeping(false);
  const engine::RigidCushionContact cushion = p.cushion->rigidContact(p);
  const engine::RigidBallContact ball_ball = p.ball_ball->rigidContact(p, kBallFrictionSlip_mps);
  ContactRecorder recorder(calibratedCushionRestitution(p), cushion.friction, ball_ball.restitution,
                           ball_ball.friction, kRestitutionThreshold_mps / unit_m);
  engine::SimulationResult result;
  recorder.events = &result.events;
  recorder.unit_m = unit_m;
  recorder.nose_spin_per_impulse =
      R * cushion.contact_sin_theta / (engine::BallProperties::kInertiaFactor * mass * R * R);
  world.SetContactListener(&recorder);

  // Cushions: one static body holding every chain.
  std::vector<std::unique_ptr<ChainTags>> tags;
  b2BodyDef boundary_def;
  b2Body* boundary = world.CreateBody(&boundary_def);
  const double skin_m = b2_polygonRadius * unit_m;
  for (const Polyline& chain :
       boundaryChains(table, skin_m, kShortestEdgeSlops * b2_linearSlop * unit_m)) {
    const bool closed = chain.points.size() > 3 &&
                        (chain.points.front() - chain.points.back()).norm() < kJoinTolerance_m;
    Polyline open = chain;
    if (closed) open.points.pop_back();  // a loop lists each vertex once
    const std::vector<Eigen::Vector2d> moved = setBack(open, closed, skin_m);
    std::vector<b2Vec2> vertices;
    for (const Eigen::Vector2d& q : moved) vertices.push_back(toBox(q));
    b2ChainShape shape;
    if (closed) {
      shape.CreateLoop(vertices.data(), static_cast<int32>(vertices.size()));
    } else {  // ghost vertices continue the end edges straight on
      const b2Vec2 before = vertices[0] + (vertices[0] - vertices[1]);
      const std::size_t n = vertices.size();
      const b2Vec2 after = vertices[n - 1] + (vertices[n - 1] - vertices[n - 2]);
      shape.CreateChain(vertices.data(), static_cast<int32>(n), before, after);
    }
    tags.push_back(std::make_unique<ChainTags>(ChainTags{chain.tags}));
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.userData.pointer = reinterpret_cast<uintptr_t>(tags.back().get());
    boundary->CreateFixture(&fixture);
  }

  std::vector<Ball> balls(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = toBox(input[i].position);
    def.linearVelocity = toBox(input[i].velocity.head<2>());
    def.angularVelocity = static_cast<float>(input[i].angular_velocity.z());
    def.userData.pointer = i + 1;
    balls[i].body = world.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(R / unit_m);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = 1;  // replaced by the ball's own mass data below
    balls[i].body->CreateFixture(&fixture);
    b2MassData mass_data;
    mass_data.mass = static_cast<float>(mass);
    mass_data.center.SetZero();
    mass_data.I = static_cast<float>(engine::BallProperties::kInertiaFactor * mass * (R / unit_m) *
                                     (R / unit_m));
    balls[i].body->SetMassData(&mass_data);
    balls[i].horizontal_spin_radps = input[i].angular_velocity.head<2>();
  }

  // The state the cloth model sees: Box2D's velocity and spin about z, the kept horizontal spin.
  auto stateOf = [&](const Ball& ball) {
    BallState s;
    const b2Vec2 q = ball.body->GetPosition(), v = ball.body->GetLinearVelocity();
    s.position = {q.x * unit_m, q.y * unit_m};
    s.velocity = {v.x * unit_m, v.y * unit_m, 0};
    s.angular_velocity = {ball.horizontal_spin_radps.x(), ball.horizontal_spin_radps.y(),
                          ball.body->GetAngularVelocity()};
    return s;
  };
  recorder.balls = &balls;
  std::vector<engine::BallRecord> records(input.size());
  // The cloth over half a step, in closed form: applied before and after each Box2D step (Strang
  // splitting), so that Box2D moves every ball with its mid-step velocity and the cloth's effect
  // on positions is second order in dt instead of first.
  auto clothHalfStep = [&](Ball& ball) {
    const BallState next = physics::advance(p.cloth, stateOf(ball), dt / 2);
    ball.body->SetLinearVelocity(toBox(next.velocity.head<2>()));
    ball.body->SetAngularVelocity(static_cast<float>(next.angular_velocity.z()));
    ball.horizontal_spin_radps = next.angular_velocity.head<2>();
    return next;
  };
  for (long step = 0;; ++step) {
    const double now = static_cast<double>(step) * dt;
    bool moving = false;
    for (Ball& ball : balls) {
      if (ball.body == nullptr) continue;
      if (physics::motionState(p.cloth, stateOf(ball)) == physics::MotionState::Stationary) {
        // Exactly at rest: Box2D's float state may carry a rounding of the cloth's zero.
        ball.body->SetLinearVelocity(b2Vec2(0, 0));
        ball.body->SetAngularVelocity(0);
        continue;
      }
      moving = true;
    }
    if (!moving || now >= settings.stop_after_s) {
      for (std::size_t i = 0; i < balls.size(); ++i)
        if (balls[i].body != nullptr) records[i].state = stateOf(balls[i]);
      result.end_time_s = now;
      break;
    }
    if (now > kMaxBox2dShotTime_s) {
      throw std::runtime_error("the Box2D shot is still moving after " +
                               physics::valueText(kMaxBox2dShotTime_s) + " s");
    }
    for (Ball& ball : balls) {
      if (ball.body == nullptr) continue;
      const BallState mid = clothHalfStep(ball);
      ball.body->SetBullet(mid.velocity.norm() * dt > kBulletTravelPerRadius * R);
    }
    recorder.now_s = now + dt;
    world.Step(static_cast<float>(dt), settings.velocity_iterations, settings.position_iterations);
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].body == nullptr) continue;
      const BallState s = clothHalfStep(balls[i]);
      for (int k = 0; k < static_cast<int>(table.pockets.size()); ++k) {
        const engine::Circle& pocket = table.pockets[k];
        if ((s.position - pocket.centre_m).squaredNorm() < pocket.radius_m * pocket.radius_m) {
          records[i].state = s;
          records[i].pocketed = true;
          world.DestroyBody(balls[i].body);
          balls[i].body = nullptr;
          engine::Event event;
          event.time_s = now + dt;
          event.kind = EventKind::Pocket;
          event.ball = static_cast<int>(i);
          event.index = k;
          result.events.push_back(event);
          break;
        }
      }
    }
  }
  result.final_balls = records;
  return result;
}

}  // namespace baize::engine
