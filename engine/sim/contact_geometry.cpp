#include "engine/sim/contact_geometry.h"

#include <cmath>

namespace baize::engine {

ContactFrame::ContactFrame(const Eigen::Vector2d& n) : x(-n.y(), n.x(), 0), y(-n.x(), -n.y(), 0) {}

physics::BallVelocity ContactFrame::toLocal(const physics::BallState& ball) const {
  physics::BallVelocity local;
  local.v = {ball.velocity.dot(x), ball.velocity.dot(y), 0};
  local.w = {ball.angular_velocity.dot(x), ball.angular_velocity.dot(y), ball.angular_velocity.z()};
  return local;
}

void ContactFrame::toTable(const physics::BallVelocity& local, physics::BallState* ball) const {
  ball->velocity = local.v.x() * x + local.v.y() * y;
  ball->velocity.z() = 0;
  ball->angular_velocity = local.w.x() * x + local.w.y() * y + Eigen::Vector3d(0, 0, local.w.z());
}

bool onJawArc(const JawArc& jaw, const Eigen::Vector2d& q) {
  double angle = std::atan2(q.y() - jaw.centre_m.y(), q.x() - jaw.centre_m.x());
  while (angle < jaw.start_angle_rad) angle += 2 * M_PI;
  return angle <= jaw.end_angle_rad;
}

bool besideSegment(const CushionSegment& cushion, const Eigen::Vector2d& q) {
  const Eigen::Vector2d along = cushion.end_m - cushion.start_m;
  const double s = (q - cushion.start_m).dot(along) / along.squaredNorm();
  return s >= 0 && s <= 1;
}

Eigen::Vector2d contactNormal(const TableGeometry& table, EventKind kind, int index,
                              const Eigen::Vector2d& position) {
  if (kind == EventKind::Cushion) return table.cushions[index].inward_normal;
  return (position - table.jaws[index].centre_m).normalized();
}

}  // namespace baize::engine
