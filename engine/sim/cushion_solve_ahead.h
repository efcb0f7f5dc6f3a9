// Cushion impacts solved ahead on a second core. When a ball's earliest predicted event is a
// cushion or jaw contact while other balls move, its state at that instant is already known
// exactly, so a helper thread solves the impact while the event loop resolves the events before
// it. At the contact the loop takes the helper's answer only if the helper solved exactly the
// input the loop has then (compared bit for bit), and otherwise solves the impact itself. The
// answer is the same function of the same input either way (the helper solves in the loop's
// floating-point environment): results are identical to the bit with or without the helper.
//
// One helper serves the process, one shot at a time, and only shots that run back to back (a
// bench, a search over many shots): a shot uses it only if it finds it awake on another core, and
// a shot that started within kAwakeAfterShot of the last one's end wakes it (the first time: starts
// it) as it ends, to stay awake that long. A shot on its own (one `baize simulate`, the viewer)
// never waits for a thread to start or wake, and never shares its core with the helper. A program
// that runs shots on several threads of its own turns the helper off (setEnabled).
#pragma once

#include <chrono>
#include <vector>

#include "physics/cushion_model.h"

namespace baize::engine {

struct SimulationParams;  // engine/sim/shot_simulator.h

class CushionSolveAhead {
 public:
  // How long the helper stays awake after a shot, for the next one.
  static constexpr std::chrono::microseconds kAwakeAfterShot{2000};

  // Whether shots may use the helper (on by default).
  static void setEnabled(bool enabled);
  static bool enabled();
  // Whether the helper can run here at all: enabled, two or more cores in the calling thread's
  // affinity mask and a cgroup CPU limit, if any, of two cores or more (read once), and its thread
  // started (or startable).
  static bool available();
  // Starts or wakes the helper and returns once it is awake (or after 0.1 s): shots in the next
  // kAwakeAfterShot find it awake (tests).
  static void wakeHelper();
  // Since the program started (for tests and benchmarks; these depend on timing, so no result
  // reports them): shots the helper served, and impacts whose answer the loop took from it.
  static long shotsServed();
  static long impactsTakenAhead();

  CushionSolveAhead(const SimulationParams& params, int ball_count);
  // Releases the helper (an impact it is still solving finishes on its own copy of the inputs),
  // or wakes it for the next shot (see above).
  ~CushionSolveAhead();
  CushionSolveAhead(const CushionSolveAhead&) = delete;
  CushionSolveAhead& operator=(const CushionSolveAhead&) = delete;

  // Whether predictions can still be handed over in this shot (the helper is held, or was not
  // asked for yet); if not, the loop need not compute them.
  bool mayUse() const { return helper_ != nullptr || !claim_tried_; }
  // Ball `ball`'s earliest event is a contact at `event_time_s` with `incoming` (local cushion
  // frame, moving into it); replaces its earlier prediction. The first call asks for the helper.
  void predict(int ball, double event_time_s, const physics::BallVelocity& incoming);
  // Ball `ball`'s prediction no longer holds.
  void forget(int ball);
  // The outcome of ball `ball`'s impact with `incoming`: the helper's if it solved exactly this
  // input, the loop's own solve otherwise.
  physics::BallVelocity resolve(int ball, const physics::BallVelocity& incoming);

  class Helper;

 private:
  const SimulationParams& params_;
  const std::chrono::steady_clock::time_point started_;
  Helper* helper_ = nullptr;      // held for this shot; null: the loop solves every impact
  bool claim_tried_ = false;      // asked once per shot, at its first prediction
  std::vector<int> job_of_ball_;  // the helper's job holding each ball's prediction; -1: none
};

}  // namespace baize::engine
