// One shot's use of a CushionImpactWorker (engine/sim/cushion_impact_worker.h): the event loop
// hands a ball's coming cushion or jaw impact over when it is predicted, and at the contact takes
// the worker's answer only if the worker solved exactly the input the loop has then (compared bit
// for bit); otherwise it solves the impact itself. The answer is the same function of the same
// input either way (the worker solves in the loop's floating-point environment): results are
// identical to the bit with or without a worker. Without one, every impact is solved in the loop.
#pragma once

#include <vector>

#include "engine/sim/cushion_impact_worker.h"
#include "physics/cushion_model.h"

namespace baize::engine {

struct SimulationParams;  // engine/sim/simulation_params.h

class CushionSolveAhead {
 public:
  // `worker` may be null: then nothing is handed over.
  CushionSolveAhead(const SimulationParams& params, int ball_count, CushionImpactWorker* worker);
  // Releases the worker (an impact it is still solving finishes on its own copy of the inputs).
  ~CushionSolveAhead();
  CushionSolveAhead(const CushionSolveAhead&) = delete;
  CushionSolveAhead& operator=(const CushionSolveAhead&) = delete;

  // Whether predictions can still be handed over in this shot (the worker is held, or was not
  // asked for yet); if not, the loop need not compute them.
  bool mayUse() const { return held_ != nullptr || (worker_ != nullptr && !claim_tried_); }
  // Ball `ball`'s earliest event is a contact at `event_time_s` with `incoming` (local cushion
  // frame, moving into it); replaces its earlier prediction. The first call asks for the worker.
  void predict(int ball, double event_time_s, const physics::BallVelocity& incoming);
  // Ball `ball`'s prediction no longer holds.
  void forget(int ball);
  // The outcome of ball `ball`'s impact with `incoming`: the worker's if it solved exactly this
  // input, the loop's own solve otherwise.
  physics::BallVelocity resolve(int ball, const physics::BallVelocity& incoming);

 private:
  const SimulationParams& params_;
  CushionImpactWorker* worker_;          // handed over by the caller, or null
  CushionImpactWorker* held_ = nullptr;  // the worker, held for this shot
  bool claim_tried_ = false;             // asked once per shot, at its first prediction
  std::vector<int> job_of_ball_;  // the worker's job holding each ball's prediction; -1: none
};

}  // namespace baize::engine
