#include "physics/cushion_simple_model.h"

#include "physics/value_text.h"

namespace baize::physics {

void validateSimpleCushionParams(const SimpleCushionParams& params) {
  requireFinite("simple cushion restitution e", params.restitution);
  if (!(params.restitution > 0 && params.restitution <= 1)) {
    rejectValue("simple cushion restitution e", params.restitution, "it must lie in (0, 1]");
  }
}

BallVelocity simpleCushionRebound(const SimpleCushionParams& params, const BallVelocity& incoming) {
  validateSimpleCushionParams(params);
  validateIncomingBall(incoming);
  BallVelocity after = incoming;
  after.v.y() = -params.restitution * incoming.v.y();
  return after;
}

}  // namespace baize::physics
