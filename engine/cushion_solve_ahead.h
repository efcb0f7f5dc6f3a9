// Cushion impacts solved ahead on a second core. When a ball's earliest predicted event is a
// cushion or jaw contact while other balls move, its state at that instant is already known
// exactly, so a helper thread solves the impact while the event loop resolves the events before
// it. At the contact the loop takes the helper's answer only if the helper solved exactly the
// input the loop has then (compared bit for bit), and otherwise solves the impact itself. The
// answer is the same function of the same input either way: results are identical to the bit with
// or without the helper, on any number of cores.
//
// One helper serves the process, one shot at a time: a shot claims it at its first prediction if
// it is free (a shot on another thread may hold it; that shot's impacts are then all solved by its
// own loop). A program that runs shots on several threads of its own turns it off (setEnabled), so
// that it does not compete with them for the cores.
#pragma once

#include <vector>

#include "physics/cushion_model.h"

namespace baize::engine {

struct SimulationParams;  // engine/shot_simulator.h

class CushionSolveAhead {
 public:
  // Whether shots may claim the helper: on by default on a machine with two or more cores.
  static void setEnabled(bool enabled);
  static bool enabled();
  // Impacts whose answer the loop took from the helper, since the program started (for tests and
  // benchmarks; how many depends on timing, so no result reports it).
  static long impactsTakenAhead();

  CushionSolveAhead(const SimulationParams& params, int ball_count);
  // Releases the helper; an impact it is still solving finishes on its own copy of the inputs.
  ~CushionSolveAhead();
  CushionSolveAhead(const CushionSolveAhead&) = delete;
  CushionSolveAhead& operator=(const CushionSolveAhead&) = delete;

  // Ball `ball`'s earliest event is a contact at `event_time_s` with `incoming` (local cushion
  // frame, moving into it); replaces its earlier prediction.
  void predict(int ball, double event_time_s, const physics::BallVelocity& incoming);
  // Ball `ball`'s prediction no longer holds.
  void forget(int ball);
  // The outcome of ball `ball`'s impact with `incoming`: the helper's if it solved exactly this
  // input, the loop's own solve otherwise.
  physics::BallVelocity resolve(int ball, const physics::BallVelocity& incoming);

  class Helper;

 private:
  const SimulationParams& params_;
  Helper* helper_ = nullptr;  // claimed at the first prediction; null: the loop solves every impact
  bool claim_tried_ = false;
  std::vector<int> job_of_ball_;  // the helper's job holding each ball's prediction; -1: none
};

}  // namespace baize::engine
