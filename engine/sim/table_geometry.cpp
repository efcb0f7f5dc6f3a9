#include "engine/sim/table_geometry.h"

#include <algorithm>
#include <cmath>

#include "physics/value_text.h"

namespace baize::engine {

using Eigen::Vector2d;

Eigen::Vector2d JawArc::pointAt(double angle_rad) const {
  return centre_m + radius_m * Eigen::Vector2d(std::cos(angle_rad), std::sin(angle_rad));
}

std::vector<Eigen::Vector2d> cushionOutline(const std::vector<CushionSegment>& cushions) {
  std::vector<Eigen::Vector2d> outline;
  outline.reserve(2 * cushions.size());
  for (const CushionSegment& c : cushions) {
    outline.push_back(c.start_m);
    outline.push_back(c.end_m);
  }
  return outline;
}

bool insideOutline(const std::vector<Eigen::Vector2d>& outline, const Eigen::Vector2d& point) {
  bool inside = false;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    const Vector2d& p = outline[i];
    const Vector2d& q = outline[j];
    if ((p.y() > point.y()) != (q.y() > point.y()) &&
        point.x() < (q.x() - p.x()) * (point.y() - p.y()) / (q.y() - p.y()) + p.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// The rail box is shrunk by this much, m, so that the rails on its sides do not count as crossing
// it and points in it lie strictly inside the outline: far below any ball's size, far above the
// rounding of table coordinates (~1e-16 m).
constexpr double kRailBoxInset_m = 1e-9;

Eigen::AlignedBox2d railBoxInsideOutline(const std::vector<Vector2d>& outline) {
  Eigen::AlignedBox2d box;
  for (const Vector2d& p : outline) box.extend(p);
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2d& p = outline[i];
    const Vector2d& q = outline[(i + 1) % n];
    // Counterclockwise: the inside lies to the left of each edge.
    if (p.y() == q.y() && p.x() != q.x()) {
      if (q.x() > p.x())
        box.min().y() = std::max(box.min().y(), p.y());
      else
        box.max().y() = std::min(box.max().y(), p.y());
    } else if (p.x() == q.x() && p.y() != q.y()) {
      if (q.y() > p.y())
        box.max().x() = std::min(box.max().x(), p.x());
      else
        box.min().x() = std::max(box.min().x(), p.x());
    }
  }
  const Vector2d inset(kRailBoxInset_m, kRailBoxInset_m);
  box = Eigen::AlignedBox2d(box.min() + inset, box.max() - inset);
  if (n < 3 || box.isEmpty()) return Eigen::AlignedBox2d();
  for (auto corner : {Eigen::AlignedBox2d::BottomLeft, Eigen::AlignedBox2d::BottomRight,
                      Eigen::AlignedBox2d::TopRight, Eigen::AlignedBox2d::TopLeft}) {
    if (!insideOutline(outline, box.corner(corner))) return Eigen::AlignedBox2d();
  }
  // No edge may reach into the box (Liang-Barsky: the part of the edge within the box's slabs).
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2d& p = outline[i];
    const Vector2d d = outline[(i + 1) % n] - p;
    double t0 = 0, t1 = 1;
    for (int axis = 0; axis < 2 && t0 <= t1; ++axis) {
      if (d[axis] == 0) {
        if (p[axis] <= box.min()[axis] || p[axis] >= box.max()[axis]) t0 = 2;  // outside the slab
        continue;
      }
      double a = (box.min()[axis] - p[axis]) / d[axis], b = (box.max()[axis] - p[axis]) / d[axis];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    if (t0 < t1) return Eigen::AlignedBox2d();
  }
  return box;
}

TableGeometry rectangularTable(double length_m, double width_m) {
  if (!(length_m > 0 && std::isfinite(length_m)))
    physics::rejectValue("table length (m)", length_m, "it must be > 0");
  if (!(width_m > 0 && std::isfinite(width_m)))
    physics::rejectValue("table width (m)", width_m, "it must be > 0");
  const double x = length_m / 2, y = width_m / 2;
  TableGeometry table;
  table.cushions = {{{-x, -y}, {x, -y}, {0, 1}},
                    {{x, -y}, {x, y}, {-1, 0}},
                    {{x, y}, {-x, y}, {0, -1}},
                    {{-x, y}, {-x, -y}, {1, 0}}};
  table.outline = cushionOutline(table.cushions);
  table.rail_box = railBoxInsideOutline(table.outline);
  return table;
}

}  // namespace baize::engine
