// The cushion impacts of rolling balls, answered from a table of the exact solver's solutions.
//
// The Mathavan 2010 model is linear in the incoming velocities: in units of V0 (velocities) and
// V0/R (spins) the outcome depends only on the direction of approach and the spin relative to
// V0/R. A ball rolling on the cloth has its horizontal spin locked to its velocity, so for one
// ball, cushion and cloth its outcome is a function of two numbers: the angle of approach alpha and
// the sidespin ratio sigma = R w_z / V0. This surface covers that plane with square cells, each an
// interpolating Chebyshev polynomial (kDegree in each variable) through the exact solver's
// solutions at tolerance kNodeTolerance, built the first time an impact falls in it and kept only
// after its error, checked against the exact solver at another set of points (corners and edges
// included), is within kCellCheckError V0. A cell that misses it is split in four, down to
// kMaxDepth; one that still misses it (a stick or slip onset crossing it, where the outcome has a
// kink) is marked, and its impacts go to the exact solver, as does every ball that is not rolling
// or lies outside the plane's covered part. The table covers sidespin >= 0 and answers the rest
// through the mirror image, so mirror-image impacts get mirror-image answers. Built lazily, so a
// run pays only for the cells its impacts touch; cached per parameter set for the process
// (rollingSurfaceFor).
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "physics/cushion_model.h"

namespace baize::physics {

// Cost and coverage of a surface so far.
struct RollingSurfaceStats {
  long cells_built = 0;      // cells whose nodes and checks were solved (kept, split or marked)
  long cells_kept = 0;       // cells answering by interpolation
  long cells_to_exact = 0;   // cells at kMaxDepth that missed the check: their impacts go exact
  long exact_solves = 0;     // exact solutions spent on building
  double build_seconds = 0;  // wall time spent building
};

// The table's promise: each answer within this of the converged solution, in V0 (velocities) and
// V0/R (spins, as R w). (The default path, which also solves the impacts the table does not
// answer, promises more loosely: kTabulatedPathPromise in cushion_tabulated_solver.h.)
constexpr double kRollingTablePromise = 1e-8;

class CushionRollingSurface {
 public:
  // Polynomial degree in each variable; (kDegree + 1)^2 nodes per cell.
  static constexpr int kDegree = 7;
  static constexpr int kNodes = kDegree + 1;
  static constexpr int kOutputs = 5;  // v_x, v_y (V0); w_x, w_y, w_z (V0/R)

  explicit CushionRollingSurface(const CushionParams& params);
  ~CushionRollingSurface();
  CushionRollingSurface(const CushionRollingSurface&) = delete;
  CushionRollingSurface& operator=(const CushionRollingSurface&) = delete;

  // The outgoing ball of a rolling incoming ball the surface answers; nothing when the ball is not
  // rolling, lies outside the covered plane or in a cell marked for the exact solver. Throws
  // std::invalid_argument as the exact solver does for an invalid incoming ball. Thread-safe.
  std::optional<BallVelocity> answer(const BallVelocity& incoming);

  RollingSurfaceStats stats() const;

  struct Cell;

 private:
  Cell& rootCellAt(double alpha_rad, double sidespin_ratio) const;
  void buildOnce(Cell* cell);
  void build(Cell* cell);

  const CushionParams params_;
  // The root cells, made (not built) with the surface: the grid never changes, so it is read
  // without a lock.
  std::vector<std::unique_ptr<Cell>> roots_;
  // Guards building and the stats. A cell's state is published (release) only once its
  // coefficients or children are complete, and never changes after that, so answers read the
  // built cells without the lock: threads answering impacts at once do not wait on each other.
  mutable std::mutex build_mutex_;
  RollingSurfaceStats stats_;
};

// The surface of `params`, made on first use and kept for the process. Thread-safe. Throws
// std::invalid_argument for invalid parameters.
CushionRollingSurface& rollingSurfaceFor(const CushionParams& params);

}  // namespace baize::physics
