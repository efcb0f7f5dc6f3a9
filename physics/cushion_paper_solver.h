// The Mathavan 2010 paper's numerical scheme (section 3.4): explicit Euler in the cushion normal
// impulse P with a fixed increment dP = (1 + e_e) M v_y0 / N, friction directions frozen over each
// increment, and trapezoidal accumulation of the normal work (eq. 17a). First order: its error
// shrinks as 1/N. Kept as the reference that reproduces the publication; the exact solver is the
// one to use.
#pragma once

#include "physics/cushion_model.h"

namespace baize::physics {

// N is an integer in [1, kMaxPaperSteps]: 1e7 increments already take about a second per impact,
// so more is a typing slip, not a wish for accuracy.
inline constexpr int kMaxPaperSteps = 10000000;
// The kinetic energy a paper-scheme impact may gain, relative: rounding only. More means its
// increments are too coarse for the impact (the scheme is first order), and callers refuse it.
inline constexpr double kPaperEnergyGrowthAllowed = 1e-12;

struct PaperSolverOptions {
  int steps = 5000;           // N in the paper, in [1, kMaxPaperSteps]
  bool record_trace = false;  // keep the state after every increment in result.trace
};

// Throws std::invalid_argument on invalid parameters, incoming state or options.
CushionImpactResult solveCushionImpactPaper(const CushionParams& params,
                                            const BallVelocity& incoming,
                                            const PaperSolverOptions& options = {});

}  // namespace baize::physics
