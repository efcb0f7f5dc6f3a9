// A generic Dormand-Prince 8(5,3) integrator (Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed.,
// section II.10) for autonomous systems dy/dt = f(y): the twelve stages of a step (the last
// evaluation reused as the next step's first), the error estimate from the embedded 5th- and
// 3rd-order solutions, a dense output between a step's ends, and the location of the root of an
// event function along a step. Templates over the state vector type (any fixed-size Eigen column
// vector) and the rate function (anything callable as Vector(const Vector&)); it knows nothing of
// the models that use it (the exact cushion solver, the Mathavan 2014 ball-ball model).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace baize::physics::dop853 {

// The pair's coefficients (the source above, table of section II.10). The stage nodes c_i are not
// needed: the rates do not depend on the independent variable (carry it in the state if needed).
constexpr double a21 = 5.26001519587677318785587544488e-2;
constexpr double a31 = 1.97250569845378994544595329183e-2, a32 = 5.91751709536136983633785987549e-2;
constexpr double a41 = 2.95875854768068491816892993775e-2, a43 = 8.87627564304205475450678981324e-2;
constexpr double a51 = 2.41365134159266685502369798665e-1,
                 a53 = -8.84549479328286085344864962717e-1,
                 a54 = 9.24834003261792003115737966543e-1;
constexpr double a61 = 3.7037037037037037037037037037e-2, a64 = 1.70828608729473871279604482173e-1,
                 a65 = 1.25467687566822425016691814123e-1;
constexpr double a71 = 3.7109375e-2, a74 = 1.70252211019544039314978060272e-1,
                 a75 = 6.02165389804559606850219397283e-2, a76 = -1.7578125e-2;
constexpr double a81 = 3.70920001185047927108779319836e-2, a84 = 1.70383925712239993810214054705e-1,
                 a85 = 1.07262030446373284651809199168e-1,
                 a86 = -1.53194377486244017527936158236e-2,
                 a87 = 8.27378916381402288758473766002e-3;
constexpr double a91 = 6.24110958716075717114429577812e-1, a94 = -3.36089262944694129406857109825e0,
                 a95 = -8.68219346841726006818189891453e-1, a96 = 2.75920996994467083049415600797e1,
                 a97 = 2.01540675504778934086186788979e1, a98 = -4.34898841810699588477366255144e1;
constexpr double a101 = 4.77662536438264365890433908527e-1,
                 a104 = -2.48811461997166764192642586468e0,
                 a105 = -5.90290826836842996371446475743e-1,
                 a106 = 2.12300514481811942347288949897e1, a107 = 1.52792336328824235832596922938e1,
                 a108 = -3.32882109689848629194453265587e1,
                 a109 = -2.03312017085086261358222928593e-2;
constexpr double a111 = -9.3714243008598732571704021658e-1,
                 a114 = 5.18637242884406370830023853209e0, a115 = 1.09143734899672957818500254654e0,
                 a116 = -8.14978701074692612513997267357e0,
                 a117 = -1.85200656599969598641566180701e1,
                 a118 = 2.27394870993505042818970056734e1, a119 = 2.49360555267965238987089396762e0,
                 a1110 = -3.0467644718982195003823669022e0;
constexpr double a121 = 2.27331014751653820792359768449e0,
                 a124 = -1.05344954667372501984066689879e1,
                 a125 = -2.00087205822486249909675718444e0,
                 a126 = -1.79589318631187989172765950534e1,
                 a127 = 2.79488845294199600508499808837e1,
                 a128 = -2.85899827713502369474065508674e0,
                 a129 = -8.87285693353062954433549289258e0,
                 a1210 = 1.23605671757943030647266201528e1,
                 a1211 = 6.43392746015763530355970484046e-1;
constexpr double b1 = 5.42937341165687622380535766363e-2, b6 = 4.45031289275240888144113950566e0,
                 b7 = 1.89151789931450038304281599044e0, b8 = -5.8012039600105847814672114227e0,
                 b9 = 3.1116436695781989440891606237e-1, b10 = -1.52160949662516078556178806805e-1,
                 b11 = 2.01365400804030348374776537501e-1, b12 = 4.47106157277725905176885569043e-2;
constexpr double bhh1 = 0.244094488188976377952755905512, bhh2 = 0.733846688281611857341361741547,
                 bhh3 = 0.220588235294117647058823529412e-1;
constexpr double er1 = 0.1312004499419488073250102996e-1, er6 = -0.1225156446376204440720569753e1,
                 er7 = -0.4957589496572501915214079952, er8 = 0.1664377182454986536961530415e1,
                 er9 = -0.3503288487499736816886487290, er10 = 0.3341791187130174790297318841,
                 er11 = 0.8192320648511571246570742613e-1,
                 er12 = -0.2235530786388629525884427845e-1;
// The 3rd-order estimate's weight in the combined error estimate.
constexpr double kThirdOrderWeight = 0.01;
// The order with which the combined error estimate scales with the step (the step controllers'
// exponent is its inverse).
constexpr double kErrorOrder = 8;
constexpr int kStages = 12;

// One term h a_ij k_j of a stage's input: the coefficient (given times h) and the rate.
template <typename Vector>
struct Term {
  double coefficient;
  const Vector* rate;
};

// z + (h c_1 k_1 + ... + h c_n k_n), element by element. The newest rate comes last, so that only
// one product and two sums wait for it (the stages run one after another, each on the one before).
template <int n, typename Vector>
Vector stageInput(const Vector& z, const std::array<Term<Vector>, n>& terms) {
  Vector y;
  for (int i = 0; i < Vector::RowsAtCompileTime; ++i) {
    double sum = terms[0].coefficient * (*terms[0].rate)[i];
    for (int j = 1; j < n; ++j) sum += terms[j].coefficient * (*terms[j].rate)[i];
    y[i] = z[i] + sum;
  }
  return y;
}

// The twelve stages' rates of a step from z (k1 given), the step's end and the rate there.
template <typename Vector>
struct Stages {
  std::array<Vector, kStages> k;
  Vector slope, end, rate_at_end;  // slope: the weighted rates, (end - z) / h
};

template <typename Vector, typename Rate>
Stages<Vector> stages(const Vector& z, const Vector& k1, double h, const Rate& rate) {
  using T = Term<Vector>;
  // The rates are made in place in the result (not copied into it after).
  Stages<Vector> result;
  std::array<Vector, kStages>& k = result.k;
  k[0] = k1;
  k[1] = rate(stageInput<1, Vector>(z, {{T{h * a21, &k[0]}}}));
  k[2] = rate(stageInput<2, Vector>(z, {{T{h * a31, &k[0]}, T{h * a32, &k[1]}}}));
  k[3] = rate(stageInput<2, Vector>(z, {{T{h * a41, &k[0]}, T{h * a43, &k[2]}}}));
  k[4] =
      rate(stageInput<3, Vector>(z, {{T{h * a51, &k[0]}, T{h * a53, &k[2]}, T{h * a54, &k[3]}}}));
  k[5] =
      rate(stageInput<3, Vector>(z, {{T{h * a61, &k[0]}, T{h * a64, &k[3]}, T{h * a65, &k[4]}}}));
  k[6] = rate(stageInput<4, Vector>(
      z, {{T{h * a71, &k[0]}, T{h * a74, &k[3]}, T{h * a75, &k[4]}, T{h * a76, &k[5]}}}));
  k[7] = rate(stageInput<5, Vector>(z, {{T{h * a81, &k[0]}, T{h * a84, &k[3]}, T{h * a85, &k[4]},
                                         T{h * a86, &k[5]}, T{h * a87, &k[6]}}}));
  k[8] =
      rate(stageInput<6, Vector>(z, {{T{h * a91, &k[0]}, T{h * a94, &k[3]}, T{h * a95, &k[4]},
                                      T{h * a96, &k[5]}, T{h * a97, &k[6]}, T{h * a98, &k[7]}}}));
  k[9] = rate(stageInput<7, Vector>(
      z, {{T{h * a101, &k[0]}, T{h * a104, &k[3]}, T{h * a105, &k[4]}, T{h * a106, &k[5]},
           T{h * a107, &k[6]}, T{h * a108, &k[7]}, T{h * a109, &k[8]}}}));
  k[10] = rate(stageInput<8, Vector>(
      z, {{T{h * a111, &k[0]}, T{h * a114, &k[3]}, T{h * a115, &k[4]}, T{h * a116, &k[5]},
           T{h * a117, &k[6]}, T{h * a118, &k[7]}, T{h * a119, &k[8]}, T{h * a1110, &k[9]}}}));
  k[11] = rate(
      stageInput<9, Vector>(z, {{T{h * a121, &k[0]}, T{h * a124, &k[3]}, T{h * a125, &k[4]},
                                 T{h * a126, &k[5]}, T{h * a127, &k[6]}, T{h * a128, &k[7]},
                                 T{h * a129, &k[8]}, T{h * a1210, &k[9]}, T{h * a1211, &k[10]}}}));
  Vector& slope = result.slope;
  for (int i = 0; i < Vector::RowsAtCompileTime; ++i) {
    slope[i] = b1 * k[0][i] + b6 * k[5][i] + b7 * k[6][i] + b8 * k[7][i] + b9 * k[8][i] +
               b10 * k[9][i] + b11 * k[10][i] + b12 * k[11][i];
  }
  result.end = z + h * slope;
  result.rate_at_end = rate(result.end);
  return result;
}

// The differences (per unit step) of the 8th-order solution from the embedded 3rd-order one and
// of the embedded 5th-order one from it, for the first Out::RowsAtCompileTime components of the
// stages (a caller whose stages carry extra components may leave them out of the estimate).
// Always inlined: called once per step on the hot path, out of line it cost the exact cushion
// solver about 2 % more instructions per impact (the stages go through memory).
template <typename Out, typename Vector>
[[gnu::always_inline]] inline void errorDifferences(const Stages<Vector>& s, Out* third,
                                                    Out* fifth) {
  const std::array<Vector, kStages>& k = s.k;
  const Vector& k1 = k[0];
  const Vector &k6 = k[5], &k7 = k[6], &k8 = k[7], &k9 = k[8], &k10 = k[9], &k11 = k[10],
               &k12 = k[11];
  for (int i = 0; i < Out::RowsAtCompileTime; ++i) {
    (*third)[i] = s.slope[i] - bhh1 * k1[i] - bhh2 * k9[i] - bhh3 * k12[i];
    (*fifth)[i] = er1 * k1[i] + er6 * k6[i] + er7 * k7[i] + er8 * k8[i] + er9 * k9[i] +
                  er10 * k10[i] + er11 * k11[i] + er12 * k12[i];
  }
}

// The combined error estimate |h| e5^2 / sqrt(n (e5^2 + w e3^2)) from the squared norms of the
// differences, each already divided by its component's error scale (n components): about the
// 8th-order solution's error in units of those scales. 0 when both vanish.
double combinedError(double fifth_squared, double third_squared, int n, double h);

// The error of a step from z to end with the given stages, as combinedError, each component's
// error divided by scale[i] (its absolute error allowance).
template <typename Vector>
double stepError(const Stages<Vector>& s, const Vector& scale, double h) {
  Vector third, fifth;
  errorDifferences(s, &third, &fifth);
  double third_squared = 0, fifth_squared = 0;
  for (int i = 0; i < Vector::RowsAtCompileTime; ++i) {
    const double t = third[i] / scale[i], f = fifth[i] / scale[i];
    third_squared += t * t;
    fifth_squared += f * f;
  }
  return combinedError(fifth_squared, third_squared, Vector::RowsAtCompileTime, h);
}

// The step factor of the standard controller, safety x error^(-1/8), within [min, max] (min for
// a NaN error: that step failed).
double stepFactor(double error, double safety, double min_factor, double max_factor);

// Dense output between a step's ends from its end values and rates (the cubic Hermite
// interpolant: no extra evaluation; its error is O(h^4) of the step, so it serves to find where
// something happens inside a step, not as a solution of the step's order).
template <typename Vector>
struct DenseOutput {
  Vector start, start_rate, end, end_rate;
  double h = 0;
  // The state at the share theta in [0, 1] of the step.
  Vector at(double theta) const {
    const double t = theta, u = 1 - theta;
    const double h00 = (1 + 2 * t) * u * u, h10 = t * u * u, h01 = t * t * (3 - 2 * t),
                 h11 = t * t * (t - 1);
    return h00 * start + (h10 * h) * start_rate + h01 * end + (h11 * h) * end_rate;
  }
};

// The root in (0, 1) of the cubic with values g0 > 0 and g1 <= 0 and slopes d0, d1 at 0 and 1
// (bisection safeguarded Newton; the cubic need not be monotone, the bracket keeps it in range):
// an event function's Hermite interpolant along a step, from its values and slopes at the ends.
double hermiteRoot(double g0, double d0, double g1, double d1);

// A bracket [lo, hi] on the root of a function positive before it (value g_lo > 0 at lo, g_hi <= 0
// at hi), narrowed by the Illinois variant of regula falsi: when the same end moves twice in a row
// the other end's value is halved, so that neither end sticks.
struct IllinoisBracket {
  double lo, g_lo, hi, g_hi;
  int side = 0;  // the end that moved last: +1 lo, -1 hi
  // The next trial: the root of the line through the ends.
  double trial() const { return (lo * g_hi - hi * g_lo) / (g_hi - g_lo); }
  // Moves the end on x's side of the root to x, where the function is g.
  void narrow(double x, double g) {
    if (g > 0) {
      lo = x, g_lo = g;
      if (side == +1) g_hi /= 2;
      side = +1;
    } else {
      hi = x, g_hi = g;
      if (side == -1) g_lo /= 2;
      side = -1;
    }
  }
};

// The search on the dense output (denseRoot) stops once its bracket is this share of the step: a
// few rounding units of the share, far below the interpolant's own error.
constexpr double kDenseBracketShare = 1e-15;

// Where along a step an event function (positive at its start, g_start, and at most zero at its
// end, g_end) reaches |event| <= tolerance on the step's dense output, as a share of the step:
// Illinois regula falsi on the interpolant, no rate evaluations; after max_iterations, or once the
// bracket is kDenseBracketShare wide, its last trial.
template <typename Vector, typename Event>
double denseRoot(const DenseOutput<Vector>& dense, double g_start, double g_end, const Event& event,
                 double tolerance, int max_iterations) {
  IllinoisBracket share{0, g_start, 1, g_end};
  double guess = 1;
  for (int it = 0; it < max_iterations && share.hi - share.lo > kDenseBracketShare; ++it) {
    guess = share.trial();
    const double g = event(dense.at(guess));
    if (std::abs(g) <= tolerance) break;
    share.narrow(guess, g);
  }
  return guess;
}

// Where along a step from z (rate k1) of length h, whose end event(end) <= tolerance crossed it,
// the event function (positive before the event) reaches |event| <= tolerance: a first guess from
// the dense output (Illinois regula falsi on it, no evaluations), then Illinois on the length of
// full steps from z (each trial a step of the pair, exact to its order). Returns the located
// length and sets *at to the state there; after max_iterations trials, the bracket's upper end
// (where the event has happened).
template <typename Vector, typename Rate, typename Event>
double locateEvent(const Vector& z, const Vector& k1, double h, const Stages<Vector>& full,
                   const Rate& rate, const Event& event, double tolerance, int max_iterations,
                   Vector* at) {
  const DenseOutput<Vector> dense{z, k1, full.end, full.rate_at_end, h};
  const double g_start = event(z), g_end = event(full.end);
  const double guess = denseRoot(dense, g_start, g_end, event, tolerance, max_iterations);
  IllinoisBracket length{0, g_start, h, g_end};
  *at = full.end;
  double trial = guess * h;
  for (int it = 0; it < max_iterations; ++it) {
    if (!(trial > length.lo && trial < length.hi)) trial = length.trial();
    const Vector y = stages(z, k1, trial, rate).end;
    const double g = event(y);
    if (std::abs(g) <= tolerance) {
      *at = y;
      return trial;
    }
    if (!(g > 0)) *at = y;  // the bracket's upper end
    length.narrow(trial, g);
    trial = length.trial();
  }
  return length.hi;
}

}  // namespace baize::physics::dop853
