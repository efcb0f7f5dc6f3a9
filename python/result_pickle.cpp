#include "python/result_pickle.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <cstring>

namespace baize::python {
namespace {

// Bumped whenever the layout below changes: an old pickle is refused, not misread.
constexpr std::int64_t kLayoutVersion = 2;

class Writer {
 public:
  void number(double x) { raw(&x, sizeof x); }
  void integer(std::int64_t n) { raw(&n, sizeof n); }
  void text(const std::string& s) {
    integer(static_cast<std::int64_t>(s.size()));
    bytes_ += s;
  }
  void state(const physics::BallState& b) {
    for (double x : {b.position.x(), b.position.y()}) number(x);
    for (int k = 0; k < 3; ++k) number(b.velocity[k]);
    for (int k = 0; k < 3; ++k) number(b.angular_velocity[k]);
  }
  std::string take() { return std::move(bytes_); }

 private:
  void raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  double number() {
    double x;
    raw(&x, sizeof x);
    return x;
  }
  std::int64_t integer() {
    std::int64_t n;
    raw(&n, sizeof n);
    return n;
  }
  // A count of items each at least `item_bytes` long, checked against the bytes left.
  std::size_t count(std::size_t item_bytes) {
    const std::int64_t n = integer();
    if (n < 0 || static_cast<std::size_t>(n) * item_bytes > bytes_.size() - at_) bad();
    return static_cast<std::size_t>(n);
  }
  std::string text() {
    const std::size_t n = count(1);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  physics::BallState state() {
    physics::BallState b;
    b.position.x() = number();
    b.position.y() = number();
    for (int k = 0; k < 3; ++k) b.velocity[k] = number();
    for (int k = 0; k < 3; ++k) b.angular_velocity[k] = number();
    return b;
  }
  bool done() const { return at_ == bytes_.size(); }
  [[noreturn]] static void bad() {
    throw pybind11::value_error("not a pickled baize.Result (or one of another layout)");
  }

 private:
  void raw(void* p, std::size_t n) {
    if (bytes_.size() - at_ < n) bad();
    std::memcpy(p, bytes_.data() + at_, n);
    at_ += n;
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

constexpr std::size_t kStateBytes = 8 * sizeof(double);

}  // namespace

std::string shotRunBytes(ShotRun& shot) {
  Writer w;
  w.integer(kLayoutVersion);
  w.text(outcomeOf(shot).cue_ball);
  w.integer(static_cast<std::int64_t>(shot.run.ball_ids.size()));
  for (const std::string& id : shot.run.ball_ids) w.text(id);
  const physics::ClothParams& c = clothOf(shot);
  for (double x : {c.radius_m, c.gravity_mps2, c.sliding_friction, c.rolling_friction,
                   c.spinning_friction})
    w.number(x);
  const engine::SimulationResult& r = recordedRunOf(shot).result;  // with its trajectories
  w.integer(static_cast<std::int64_t>(r.events.size()));
  for (const engine::Event& e : r.events) {
    w.number(e.time_s);
    for (int n : {static_cast<int>(e.kind), e.ball, e.other, e.index}) w.integer(n);
    for (const engine::EventBalls* balls : {&e.before, &e.after}) {
      w.integer(static_cast<std::int64_t>(balls->size()));
      for (const physics::BallState& b : *balls) w.state(b);
    }
  }
  w.integer(static_cast<std::int64_t>(r.final_balls.size()));
  for (const engine::BallRecord& b : r.final_balls) {
    w.state(b.state);
    w.integer(b.pocketed);
    w.integer(b.pocket);
  }
  w.number(r.end_time_s);
  w.integer(r.predictions);
  w.integer(r.skipped_predictions);
  w.integer(static_cast<std::int64_t>(r.trajectories.size()));
  for (const engine::Trajectory& t : r.trajectories) {
    w.integer(static_cast<std::int64_t>(t.size()));
    for (const engine::TrajectoryPiece& p : t) {
      w.number(p.start_time_s);
      w.state(p.state);
      w.integer(p.pocketed);
    }
  }
  const std::vector<long>& beyond = beyondModelRangeOf(shot);
  w.integer(static_cast<std::int64_t>(beyond.size()));
  for (long index : beyond) w.integer(index);
  return w.take();
}

ShotRun shotRunFromBytes(const std::string& bytes) {
  Reader r(bytes);
  if (bytes.size() < sizeof(std::int64_t) || r.integer() != kLayoutVersion) Reader::bad();
  ShotRun shot;
  shot.trajectories_recorded = true;  // read below: an unpickled result has no scene to run again
  const std::string cue_ball = r.text();
  shot.run.ball_ids.resize(r.count(8));
  for (std::string& id : shot.run.ball_ids) id = r.text();
  physics::ClothParams& c = shot.cloth.emplace();
  for (double* x : {&c.radius_m, &c.gravity_mps2, &c.sliding_friction, &c.rolling_friction,
                    &c.spinning_friction})
    *x = r.number();
  const long balls = static_cast<long>(shot.run.ball_ids.size());
  auto ballIndex = [&](std::int64_t i, bool may_be_none) {
    if (i >= balls || i < (may_be_none ? -1 : 0)) Reader::bad();
    return static_cast<int>(i);
  };
  engine::SimulationResult& result = shot.run.result;
  result.events.resize(r.count(8 * 7));
  for (engine::Event& e : result.events) {
    e.time_s = r.number();
    const std::int64_t kind = r.integer();
    if (kind < 0 || kind > static_cast<int>(engine::EventKind::Pocket)) Reader::bad();
    e.kind = static_cast<engine::EventKind>(kind);
    e.ball = ballIndex(r.integer(), false);
    e.other = ballIndex(r.integer(), true);
    e.index = static_cast<int>(r.integer());
    for (engine::EventBalls* states : {&e.before, &e.after}) {
      const std::size_t n = r.count(kStateBytes);
      if (n > engine::EventBalls::kCapacity) Reader::bad();
      for (std::size_t k = 0; k < n; ++k) states->push_back(r.state());
    }
  }
  result.final_balls.resize(r.count(kStateBytes));
  for (engine::BallRecord& b : result.final_balls) {
    b.state = r.state();
    b.pocketed = r.integer() != 0;
    b.pocket = static_cast<int>(r.integer());
  }
  result.end_time_s = r.number();
  result.predictions = r.integer();
  result.skipped_predictions = r.integer();
  result.trajectories.resize(r.count(8));
  for (engine::Trajectory& t : result.trajectories) {
    t.resize(r.count(kStateBytes));
    for (engine::TrajectoryPiece& p : t) {
      p.start_time_s = r.number();
      p.state = r.state();
      p.pocketed = r.integer() != 0;
    }
  }
  std::vector<long>& beyond = shot.beyond_model_range.emplace(r.count(8));
  for (long& index : beyond) {
    index = static_cast<long>(r.integer());
    if (index < 0 || static_cast<std::size_t>(index) >= result.events.size()) Reader::bad();
  }
  if (!r.done() || result.final_balls.size() != shot.run.ball_ids.size()) Reader::bad();
  try {
    shot.outcome = engine::shotOutcome(shot.run, cue_ball);
  } catch (const std::invalid_argument&) {
    Reader::bad();
  }
  return shot;
}

}  // namespace baize::python
