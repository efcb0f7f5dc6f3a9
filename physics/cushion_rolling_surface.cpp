#include "physics/cushion_rolling_surface.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "physics/cushion_exact_solver.h"
#include "physics/value_text.h"

namespace baize::physics {
namespace {

// The table holds outcomes per unit of incoming speed: it is right only where they scale with it.
void requireScalesWithSpeed(const CushionParams& params) {
  if (!impactScalesWithSpeed(params)) {
    throw std::invalid_argument(
        "the table of rolling cushion impacts needs an outcome that scales with the incoming "
        "speed; a speed-dependent restitution (falloff exponent " +
        valueText(params.restitution_speed_dependence->falloff_exponent) +
        ") must go to the exact solver");
  }
}

// The exact solver's tolerance at the nodes and check points: its error there (about 1e-12 V0)
// stays three decades below kCellCheckError, so a cell's check measures its interpolation error.
constexpr double kNodeTolerance = 1e-12;
// The largest error, in V0 (velocities) and V0/R (spins, as R w), a kept cell may show at its check
// points. A thousandth of the exact solver's 1e-9 V0 promise would cost many more cells; a tenth
// of kRollingTablePromise leaves room for the error between the check points.
constexpr double kCellCheckError = 1e-9;
// Splits below a root cell before a cell is marked for the exact solver: its side is then 1/32 of
// a root cell's, so the cells marked along a kink hold a small share of the plane.
constexpr int kMaxDepth = 5;
// The covered plane. alpha: grazing approaches below 1 deg (rare, and where the outcome turns
// fastest with alpha) go to the exact solver. sigma: sidespin within 6 V0/R, more than the
// impacts of play reach but for the slowest balls; negative sidespin through the mirror image.
constexpr double kMinAlpha_rad = M_PI / 180;
constexpr double kMaxAlpha_rad = M_PI - kMinAlpha_rad;
constexpr double kMaxSidespinRatio = 6;
constexpr int kRootCellsAlpha = 16;
constexpr int kRootCellsSidespin = 12;
// A ball is rolling when its slip on the cloth is within this share of V0: the event loop's
// rolling balls slip by rounding alone (about 1e-16 V0), and taking a slip this small as none
// changes the outcome by about as much, far below kCellCheckError.
constexpr double kRollingSlipShare = 1e-12;

constexpr int kNodes = CushionRollingSurface::kNodes;
constexpr int kOutputs = CushionRollingSurface::kOutputs;
constexpr int kCheckPoints = 3;  // per variable: the ends and the middle
using Outputs = std::array<double, kOutputs>;

// Chebyshev points of the first kind on [-1, 1] (the interpolation nodes) and the extrema of
// T_kNodes with the end points (the check points: where interpolation errs most).
double nodePoint(int k) { return std::cos(M_PI * (k + 0.5) / kNodes); }
double checkPoint(int m) { return std::cos(M_PI * m / (kCheckPoints - 1)); }

// T_0(x) ... T_{kNodes-1}(x).
std::array<double, kNodes> chebyshevValues(double x) {
  std::array<double, kNodes> t;
  t[0] = 1;
  t[1] = x;
  for (int i = 2; i < kNodes; ++i) t[i] = 2 * x * t[i - 1] - t[i - 2];
  return t;
}

}  // namespace

struct CushionRollingSurface::Cell {
  enum class State { Unbuilt, Kept, Split, Exact };
  double alpha0 = 0, alpha1 = 0, sigma0 = 0, sigma1 = 0;  // rad; V0/R
  int depth = 0;
  // Written once, by build, after what it publishes; read without a lock (acquire).
  std::atomic<State> state{State::Unbuilt};
  // Per output, coefficients of T_i(x) T_j(y), x and y the cell's variables mapped to [-1, 1].
  // (empty until built; freed when split or marked)
  std::vector<std::array<double, kNodes * kNodes>> coefficients;
  std::array<std::unique_ptr<Cell>, 4> children;  // when split: (alpha, sigma) low-low, high-low,
                                                  // low-high, high-high

  double x(double alpha) const { return (2 * alpha - alpha0 - alpha1) / (alpha1 - alpha0); }
  double y(double sigma) const { return (2 * sigma - sigma0 - sigma1) / (sigma1 - sigma0); }
  double alphaAt(double x) const { return 0.5 * (alpha0 + alpha1) + 0.5 * (alpha1 - alpha0) * x; }
  double sigmaAt(double y) const { return 0.5 * (sigma0 + sigma1) + 0.5 * (sigma1 - sigma0) * y; }

  Outputs interpolate(double alpha, double sigma) const {
    const std::array<double, kNodes> tx = chebyshevValues(x(alpha));
    const std::array<double, kNodes> ty = chebyshevValues(y(sigma));
    Outputs out{};
    for (int o = 0; o < kOutputs; ++o) {
      double sum = 0;
      for (int i = 0; i < kNodes; ++i) {
        double row = 0;
        for (int j = 0; j < kNodes; ++j) row += coefficients[o][i * kNodes + j] * ty[j];
        sum += row * tx[i];
      }
      out[o] = sum;
    }
    return out;
  }

  Cell* childAt(double alpha, double sigma) const {
    const int high_alpha = alpha >= 0.5 * (alpha0 + alpha1);
    const int high_sigma = sigma >= 0.5 * (sigma0 + sigma1);
    return children[high_alpha + 2 * high_sigma].get();
  }
};

namespace {

// The exact outcome of the rolling ball at (alpha, sigma), in V0 and V0/R.
Outputs exactOutputs(const CushionParams& params, double alpha, double sigma) {
  const double speed = 1;  // m/s: V0 = 1, so the outcome is in units of V0 already
  ExactSolverOptions options;
  options.tolerance = kNodeTolerance;
  const BallVelocity after =
      solveCushionImpactExact(
          params,
          incomingBall(speed, alpha, speed / params.radius_m, sigma * speed / params.radius_m),
          options)
          .after;
  const double R = params.radius_m;
  return {after.v.x(), after.v.y(), R * after.w.x(), R * after.w.y(), R * after.w.z()};
}

}  // namespace

CushionRollingSurface::CushionRollingSurface(const CushionParams& params) : params_(params) {
  validateCushionParams(params);
  requireScalesWithSpeed(params);
  // The grid of root cells, none built: a parameter set costs only the cells its impacts reach.
  const double alpha_step = (kMaxAlpha_rad - kMinAlpha_rad) / kRootCellsAlpha;
  const double sigma_step = kMaxSidespinRatio / kRootCellsSidespin;
  for (int s = 0; s < kRootCellsSidespin; ++s) {
    for (int a = 0; a < kRootCellsAlpha; ++a) {
      auto root = std::make_unique<Cell>();
      root->alpha0 = kMinAlpha_rad + a * alpha_step;
      root->alpha1 = a + 1 == kRootCellsAlpha ? kMaxAlpha_rad : root->alpha0 + alpha_step;
      root->sigma0 = s * sigma_step;
      root->sigma1 = s + 1 == kRootCellsSidespin ? kMaxSidespinRatio : root->sigma0 + sigma_step;
      roots_.push_back(std::move(root));
    }
  }
}

CushionRollingSurface::~CushionRollingSurface() = default;

CushionRollingSurface::Cell& CushionRollingSurface::rootCellAt(double alpha, double sigma) const {
  const auto index = [](double value, double low, double high, int cells) {
    const int i = static_cast<int>((value - low) / (high - low) * cells);
    return std::min(std::max(i, 0), cells - 1);
  };
  const int a = index(alpha, kMinAlpha_rad, kMaxAlpha_rad, kRootCellsAlpha);
  const int s = index(sigma, 0, kMaxSidespinRatio, kRootCellsSidespin);
  return *roots_[s * kRootCellsAlpha + a];
}

void CushionRollingSurface::buildOnce(Cell* cell) {
  std::lock_guard<std::mutex> lock(build_mutex_);
  if (cell->state.load(std::memory_order_relaxed) == Cell::State::Unbuilt) build(cell);
}

void CushionRollingSurface::build(Cell* cell) {
  const auto start = std::chrono::steady_clock::now();
  // Values at the nodes, then the coefficients (the discrete Chebyshev transform in each variable).
  std::array<std::array<Outputs, kNodes>, kNodes> values;
  cell->coefficients.resize(kOutputs);
  for (int k = 0; k < kNodes; ++k)
    for (int l = 0; l < kNodes; ++l)
      values[k][l] =
          exactOutputs(params_, cell->alphaAt(nodePoint(k)), cell->sigmaAt(nodePoint(l)));
  for (int i = 0; i < kNodes; ++i) {
    for (int j = 0; j < kNodes; ++j) {
      const double weight = (i == 0 ? 1.0 : 2.0) * (j == 0 ? 1.0 : 2.0) / (kNodes * kNodes);
      for (int o = 0; o < kOutputs; ++o) {
        double sum = 0;
        for (int k = 0; k < kNodes; ++k) {
          double row = 0;
          for (int l = 0; l < kNodes; ++l)
            row += values[k][l][o] * std::cos(M_PI * j * (l + 0.5) / kNodes);
          sum += row * std::cos(M_PI * i * (k + 0.5) / kNodes);
        }
        cell->coefficients[o][i * kNodes + j] = weight * sum;
      }
    }
  }
  // The check: first the last coefficients in each variable (how far the series is from
  // converged, free), then the error at the check points against the exact solver.
  double worst = 0;
  for (int o = 0; o < kOutputs; ++o) {
    for (int i = 0; i < kNodes; ++i) {
      worst = std::max(worst, std::fabs(cell->coefficients[o][i * kNodes + kNodes - 1]));
      worst = std::max(worst, std::fabs(cell->coefficients[o][(kNodes - 1) * kNodes + i]));
    }
  }
  for (int m = 0; m < kCheckPoints && worst <= kCellCheckError; ++m) {
    for (int n = 0; n < kCheckPoints && worst <= kCellCheckError; ++n) {
      const double alpha = cell->alphaAt(checkPoint(m)), sigma = cell->sigmaAt(checkPoint(n));
      const Outputs exact = exactOutputs(params_, alpha, sigma);
      const Outputs interpolated = cell->interpolate(alpha, sigma);
      for (int o = 0; o < kOutputs; ++o)
        worst = std::max(worst, std::fabs(interpolated[o] - exact[o]));
      ++stats_.exact_solves;
    }
  }
  stats_.exact_solves += kNodes * kNodes;
  ++stats_.cells_built;
  if (worst <= kCellCheckError) {
    cell->state.store(Cell::State::Kept, std::memory_order_release);
    ++stats_.cells_kept;
  } else if (cell->depth < kMaxDepth) {
    cell->coefficients = {};
    const double alpha_mid = 0.5 * (cell->alpha0 + cell->alpha1);
    const double sigma_mid = 0.5 * (cell->sigma0 + cell->sigma1);
    for (int c = 0; c < 4; ++c) {
      auto child = std::make_unique<Cell>();
      child->alpha0 = c % 2 ? alpha_mid : cell->alpha0;
      child->alpha1 = c % 2 ? cell->alpha1 : alpha_mid;
      child->sigma0 = c / 2 ? sigma_mid : cell->sigma0;
      child->sigma1 = c / 2 ? cell->sigma1 : sigma_mid;
      child->depth = cell->depth + 1;
      cell->children[c] = std::move(child);
    }
    cell->state.store(Cell::State::Split, std::memory_order_release);  // children complete
  } else {
    cell->coefficients = {};
    cell->state.store(Cell::State::Exact, std::memory_order_release);
    ++stats_.cells_to_exact;
  }
  stats_.build_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::optional<BallVelocity> CushionRollingSurface::answer(const BallVelocity& incoming) {
  validateIncomingBall(incoming);
  const double speed = std::hypot(incoming.v.x(), incoming.v.y());
  if (!(clothSlip(params_, incoming).norm() <= kRollingSlipShare * speed)) return std::nullopt;
  // The mirror image in the plane x = 0 (v_x, w_y and w_z change sign) has the mirrored outcome:
  // the table covers sidespin >= 0 and answers the rest through the mirror, so that mirror-image
  // impacts get mirror-image answers to the bit, as from the exact solver.
  const bool mirrored = incoming.w.z() < 0 || (incoming.w.z() == 0 && incoming.v.x() < 0);
  const double sign = mirrored ? -1 : 1;
  const double alpha = std::atan2(incoming.v.y(), sign * incoming.v.x());
  const double sigma = params_.radius_m * sign * incoming.w.z() / speed;
  if (!(alpha >= kMinAlpha_rad && alpha <= kMaxAlpha_rad && sigma <= kMaxSidespinRatio))
    return std::nullopt;
  Cell* cell = &rootCellAt(alpha, sigma);
  for (;;) {
    Cell::State state = cell->state.load(std::memory_order_acquire);
    if (state == Cell::State::Unbuilt) {
      buildOnce(cell);
      state = cell->state.load(std::memory_order_acquire);
    }
    if (state == Cell::State::Exact) return std::nullopt;
    if (state == Cell::State::Kept) break;
    cell = cell->childAt(alpha, sigma);
  }
  const Outputs out = cell->interpolate(alpha, sigma);
  const double spin_unit = speed / params_.radius_m;  // V0 / R
  BallVelocity after;
  after.v = Eigen::Vector3d(sign * speed * out[0], speed * out[1], 0);
  after.w =
      Eigen::Vector3d(spin_unit * out[2], sign * spin_unit * out[3], sign * spin_unit * out[4]);
  return after;
}

RollingSurfaceStats CushionRollingSurface::stats() const {
  std::lock_guard<std::mutex> lock(build_mutex_);
  return stats_;
}

CushionRollingSurface& rollingSurfaceFor(const CushionParams& params) {
  requireScalesWithSpeed(params);  // before the per-thread shortcut: its key omits the law
  using Key = std::tuple<double, double, double, double, double, double>;
  const Key key{params.mass_kg,     params.radius_m,         params.contact_height_m,
                params.restitution, params.cushion_friction, params.cloth_friction};
  // Every impact asks for its table; a shot's impacts ask for the same one. Each thread keeps the
  // last it was given (tables live for the process), so an impact takes neither the lock nor the
  // map below. A NaN never equals itself, so bad parameters always reach the check.
  thread_local Key last_key{};
  thread_local CushionRollingSurface* last_surface = nullptr;
  if (last_surface != nullptr && key == last_key) return *last_surface;
  validateCushionParams(params);  // first: a NaN would break the map's order
  static std::mutex mutex;
  static std::map<Key, std::unique_ptr<CushionRollingSurface>> surfaces;
  std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<CushionRollingSurface>& surface = surfaces[key];
  if (!surface) surface = std::make_unique<CushionRollingSurface>(params);
  last_key = key;
  last_surface = surface.get();
  return *surface;
}

}  // namespace baize::physics
