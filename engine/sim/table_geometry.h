// The geometry the event loop collides with: straight cushion noses, rounded jaw tips, pockets'
// capture circles and the outline a ball must stay inside. Tables read from files
// (engine/io/table.h) are built of these; the event loop needs nothing else of a table.
//
// Table frame: x and y in the table plane, z up; metres.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace baize::engine {

struct Circle {
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();
  double radius_m = 0;
};

// A straight cushion nose. The outline runs counterclockwise, so the inward normal (towards where
// balls roll) is the direction start -> end turned +90 degrees.
struct CushionSegment {
  Eigen::Vector2d start_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d end_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d inward_normal = Eigen::Vector2d::Zero();  // unit
  int pocket = -1;  // index of the pocket whose facing this is; -1 for a rail
};

// The rounded jaw tip: the points centre + radius (cos a, sin a) for a from start to end
// (counterclockwise, end - start = pi - facing angle). Balls touch it from outside the circle.
struct JawArc {
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();
  double radius_m = 0;
  double start_angle_rad = 0;
  double end_angle_rad = 0;
  int pocket = 0;

  Eigen::Vector2d pointAt(double angle_rad) const;
};

// What the event loop needs of a table : straight cushion noses with
// inward normals, jaw arcs touched from outside, and the pockets' capture circles (a ball whose
// centre enters one has fallen in). A ball touches a straight cushion when its centre is R from the
// line along the normal with its contact point between the ends, and a jaw when its centre is
// radius + R from the jaw's centre in a direction within the jaw's angular range (the contact
// normal then points from that centre to the ball).
//
// `outline` is the cushion outline (cushionOutline) a ball that is not pocketed
// must stay inside; simulate() fails with BallLeftTableError when a ball is found outside it after
// an event. Empty: not checked (a hand-made geometry whose cushions do not enclose the table).
// `rail_box` (railBoxInsideOutline) lies inside it: balls there skip the polygon test.
struct TableGeometry {
  std::vector<CushionSegment> cushions;
  std::vector<JawArc> jaws;
  std::vector<Circle> pockets;
  std::vector<Eigen::Vector2d> outline;
  Eigen::AlignedBox2d rail_box;  // empty: every check takes the polygon test
};

// A table with a rectangular playing area and no pockets: four cushions, inward normals, and the
// rectangle as its outline.
TableGeometry rectangularTable(double length_m, double width_m);

// The cushion outline: the ends of the straight cushion noses in turn, for noses listed in outline
// order (Table::cushions), so that jaw roundings are cut by their chords (which lie behind them)
// and pocket openings are closed by the line between the facings' deep ends. A ball centre that
// is not in a pocket stays inside it.
std::vector<Eigen::Vector2d> cushionOutline(const std::vector<CushionSegment>& cushions);

// Whether `point` lies inside the simple polygon `outline` (crossing-number test; points on the
// boundary may go either way).
bool insideOutline(const std::vector<Eigen::Vector2d>& outline, const Eigen::Vector2d& point);

// A box wholly inside a counterclockwise `outline`, bounded by its axis-aligned edges (a table's
// rails), so that a point in it needs no polygon test; empty when that box is not inside (no edge
// may cross it and its corners must be inside).
Eigen::AlignedBox2d railBoxInsideOutline(const std::vector<Eigen::Vector2d>& outline);

}  // namespace baize::engine
