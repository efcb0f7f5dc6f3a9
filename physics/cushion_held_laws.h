// The held laws of the exact cushion solver (the Mathavan 2010 model; method at the top of
// cushion_exact_solver.cpp): for a contact whose slip has vanished, whether its friction cone holds
// it, and otherwise the direction phi* in which its slip grows along itself (closed forms where the
// slip rate is affine in the friction direction, Newton's method, or a search of the circle),
// corrected for the lag of a slip growing from rest; the laws in force at given slips.
#pragma once

#include "physics/cushion_impact_equations.h"

namespace baize::physics::cushion_exact {

// A held contact sticks only while its friction lies this fraction inside its cone (rounding in the
// stick solve): at the edge it slides, so that a located break takes effect where it is located.
constexpr double kConeSlackRelative = 1e-12;

// The held laws on top of the equations (each method is described where it is defined).
class HeldLaws : public ImpactEquations {
 public:
  using ImpactEquations::ImpactEquations;
  using ImpactEquations::lagCorrected;

  // phi*, the direction a held contact slides along when its cone cannot hold it: in closed form
  // for the cloth while the nose slides, by Newton's method (exact for the nose's affine slip
  // rate), or by a search of the circle.
  bool clothCreepDirection(int k, const Laws& laws, Eigen::Vector2d* result) const;
  // The cloth's slip rate r0 without its own friction, and k, while the nose slides along
  // laws.direction[0] (or is frictionless); see clothCreepDirection.
  struct ClothDrive {
    Eigen::Vector2d rate;  // r0, m/s per N s
    double own = 0;        // k, m/s per N s
  };
  ClothDrive clothDrive(const Laws& laws) const;
  bool creepDirection(int k, Laws laws, const Eigen::Vector2d& guess,
                      Eigen::Vector2d* result) const;
  bool affineSlipRate(int k, Laws laws, Eigen::Vector2d* r0, Eigen::Matrix2d* W) const;
  enum class AffineNewton { Found, NotFound, NotAffine };
  AffineNewton creepDirectionAffineNewton(int k, Laws laws, const Eigen::Vector2d& guess,
                                          Eigen::Vector2d* result) const;
  static bool affineNewton(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                           const Eigen::Vector2d& guess, Eigen::Vector2d* result);
  bool creepDirectionAffine(int k, Laws laws, Eigen::Vector2d* result) const;
  static bool affineCreepDirection(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                                   Eigen::Vector2d* result);
  Eigen::Vector2d creepDirectionSearch(int k, Laws laws) const;
  bool clothHeldLaws(Laws* laws) const;
  // The lag of a slip growing from rest behind a turning phi*.
  double lagShare(int k, Laws laws, const Eigen::Vector2d& phi) const;
  static Eigen::Vector2d probeTurned(const Eigen::Vector2d& phi);
  static double lagShareOf(double growth, double restoring, double growth_order);
  static double affineLagShare(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                               const Eigen::Vector2d& phi, double growth_order);

  // The direction of a slip that grows from zero while phi* turns: the slip is the sum of what
  // phi* drove since it was zero, so it lags phi*. With the slip growing at g = |r0| - k from zero
  // at P0 and phi* turning steadily at psi', its direction turns at psi' |r0| / (|r0| + g) (from
  // d theta/dP = |r0| sin(psi - theta) / |u| with |u| = g (P - P0)): it has followed the share
  // weight = |r0| / (2 |r0| - k) of phi*'s turn since the origin. Without it the held law misses
  // the lag at first order and ends while the slip is still tiny.
  static Eigen::Vector2d lagCorrected(const Eigen::Vector2d& origin, const Eigen::Vector2d& phi,
                                      double weight) {
    // Between the two unit vectors by that share (normalized linear blend: its angle misses the
    // share of the angle by O(turn^3), below the O(turn^2) the correction itself leaves).
    return ((1 - weight) * origin + weight * phi).normalized();
  }

  // The laws in force at slips u, and what decides them.
  Laws lawsAt(const std::array<Eigen::Vector2d, 2>& u, std::array<double, 2>* speed) const;
  int slidesFirst(const Laws& laws, const Friction& f,
                  const std::array<Eigen::Vector2d, 2>& u) const;
  void slideAlongCreep(int k, Laws* laws) const;
  double neededMargin(int k, const State& z) const;
  double creepRoom(int k, const State& z) const;
  bool slidesSteadily(int k, const std::array<Eigen::Vector2d, 2>& u);
};

}  // namespace baize::physics::cushion_exact
