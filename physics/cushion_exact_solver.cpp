#include "physics/cushion_exact_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "physics/polynomial_roots.h"
#include "physics/value_text.h"

// How the solver works (the derivation is in docs/cushion.md).
//
// Write a = -(friction impulse rate at I) in the basis (x, Y') and b = -(friction impulse rate at
// C) in (x, y), both per unit of P. While both contacts slip, a = mu_w (cos Phi, sin Phi) and b =
// mu_s q (cos Phi', sin Phi') with q = sin th + cos th a_y (eq. 8). Every velocity is linear in P
// and in the integrals A = int a dP and B = int b dP (impulseResponse), and so are the slips:
//
//   u_I(P) = u_I(0) - (1/M) [ 7/2 A_x + (1 - 5s/2) B_x ,  (s^2 + 5/2) A_y + (5/2 - s) B_y - s c P ]
//   u_C(P) = u_C(0) - (1/M) [ (1 - 5s/2) A_x + 7/2 B_x ,  c P + (5/2 - s) A_y + 7/2 B_y ]
//
// (s = sin th, c = cos th; the 4x4 matrix is the contacts' inverse effective mass, times M.) So the
// impact is the system y = (A_x, A_y, B_x, B_y, W) with dy/dP = (a, b, c v_y). A stuck contact's
// friction is whatever keeps its slip rate zero (a linear solve), valid while inside its cone.
//
// A slipping contact's friction is along u / |u|, which turns infinitely fast as u -> 0: in P the
// equations are singular there, and steps in P chatter or crawl toward the zero. So the independent
// variable is tau with dP/dtau = sigma = prod over slipping contacts of |u| / (|u| + s0) (leaving
// out a slip that falls along its line or grows well above s0, below). In tau a slip that
// vanishes decays exponentially and one that turns does so smoothly, while a slip far above s0
// runs at sigma ~ 1. When a slip is below the vanishing threshold the contact is held: it
// sticks if its friction cone can hold it; otherwise it slides along the one direction phi* in
// which its slip grows along itself, as long as that law is accurate (an event ends it). A stuck
// contact whose cone stops holding it (an event) slips along the friction it needed, so friction
// stays continuous.
//
// Four special cases cut the cost where the general machinery is slow (docs/cushion.md, "Cost"):
// the cloth contact's phi* while the nose slides is r0 / |r0| in closed form (its own friction
// enters its slip rate isotropically); a slip growing from rest while the other contact slides
// follows a held law corrected for the lag of its direction behind phi*; a slip falling along its
// own line runs in P with its friction along that line until it vanishes, instead of decaying
// exponentially in tau; and a slip growing well above s0 runs in P too. The rates of the common
// modes (both contacts sliding, or one held while the other slides) are written out and inlined
// into the Runge-Kutta stages, which carry the slips alongside the state.
//
// The system in tau is integrated with the Dormand-Prince 8(5,3) pair, its error measured across
// the path (an error of tau alone moves no state off it), its steps capped at a few time constants
// of the fastest-turning slip direction and at one turning scale |u| / |du/dtau| of each slipping
// slip (beyond either the pair's estimate fails). The ends of compression
// (v_y = 0) and restitution (W = (1 - e^2) W_c, eq. 17b), the instants a stuck contact breaks and
// the end of a held law are events, located by Newton's method (or Illinois regula falsi) on the
// step length, each trial a full Runge-Kutta step, and a short last correction one Heun step. The
// phase ends, across which the dynamics do not change, are usually aimed at instead: a step is cut
// to end where they are predicted (extrapolated from the last step) and short third-order steps
// land on them from there.

namespace baize::physics {
namespace {

using State = Eigen::Matrix<double, 6, 1>;  // (P, A_x, A_y, B_x, B_y: N s; W: J)
enum : int { kP = 0, kAx = 1, kAy = 2, kBx = 3, kBy = 4, kWork = 5, kStateSize = 6 };
// While both contacts slide the Runge-Kutta stages also carry the slips (u_Ix, u_Iy, u_Cx, u_Cy;
// m/s), which are affine in the state: summed with the stages, they reach each stage without the
// contact matrix (see bothSlidingRate).
enum : int { kUIx = kStateSize, kUIy, kUCx, kUCy, kExtendedSize };
using Extended = Eigen::Matrix<double, kExtendedSize, 1>;

// s0 of the change of variable, as a fraction of the velocity scale: below it a slipping contact's
// own slip sets the pace (its direction turns over impulses of about M |u| / mu). A held contact
// whose slip grows to it slips on as an ordinary slipping contact.
constexpr double kRegularizingSlipFraction = 1e-3;
// A slipping contact whose slip is at least this multiple of the regularizing slip and growing
// runs in P (its factor in sigma is 1): it moves away from the zero the change of variable guards,
// and its factor's own variation (from about 0.8 toward 1 as it grows) only adds curvature in tau.
// Most such slips are a slip released from rest growing under the other contact's sliding (a ball
// rolling into the cushion): on the impacts of play 7.5 % fewer evaluations (423 to 391 per
// impact) and 2 % fewer on the pool bench's, 1 to 2 % more on the snooker bench's and the spinning
// and grippy sets', the same largest errors; 1, 2 and 10 gave 394, 393 and 399 on the impacts of
// play. Taking out of sigma every slip above it, shrinking ones too, gave 399 at 5 and 416 at 20.
constexpr double kRecedingSlipMultiple = 5;
// A slipping contact whose slip shrinks along its own line runs in P (its factor in sigma is 1)
// with its friction held along that line, as long as the turn its slip rate gives it would carry
// the slip off the line by at most this share of the misalignment limit (kCreepErrorFraction) by
// the time it reaches zero. The slip then falls linearly in P and a step or two reach its zero,
// where in tau (the slip's own factor) the same fall is an exponential decay whose direction mode
// is stiff: about a quarter of an e-fold per step, over the fifteen e-folds from the regularizing
// slip to the vanishing threshold.
constexpr double kApproachEntry = 0.25;
// The zero an approaching slip runs to is located where it is this multiple of the vanishing
// threshold, to within the looseness (so that it has vanished when located).
constexpr double kApproachLanding = 0.5;
constexpr double kApproachLooseness = 0.25;
// A slip below this fraction of (tolerance x velocity scale) has vanished. It must lie above what
// the integration resolves of a slip (impulse errors of tolerance x M V reach the slips through the
// contact matrix, whose entries are up to 7/2, as about 3.5 tolerance x V), and taking it as zero
// moves the result by about that much: the remaining impulse to its true zero is about M |u| / (7/2
// mu), over which friction of any direction changes the velocities by less than |u|. So it sets
// much of the error at any tolerance: at 5 rather than 10 the largest error over the bench's 12000
// snooker impacts at the default tolerance falls from 4.3e-10 to 2.4e-10 V0, and at 1e-8 from 2e-7
// to 7e-8 V0 (8000 wide ones), for the same evaluations. 5 keeps it 40 % above the 3.5.
constexpr double kVanishedSlipFraction = 5;
// A held contact sliding along phi* slips as its own slip says once its slip's misalignment with
// phi*
// (|u| sin angle, which measures what the held law has missed) reaches this fraction of
// (tolerance x velocity scale).
constexpr double kCreepErrorFraction = 10;
// The end of a held law is located where its error lies within this fraction of the limit either
// side of it (where exactly does not matter; a loose bracket costs fewer trial steps).
constexpr double kCreepEndLooseness = 0.5;
// A held law's step is cut to end where its error is predicted to reach this fraction of the
// limit (inside the looseness either side, so that the end is due at the next step's start), its
// rate of turn probed over this fraction of the impulse scale (far above the 1e-10 rad to which
// phi* is solved, far below the impact).
constexpr double kCreepEndAim = 0.75;
// A slipping contact is taken as sliding steadily along phi* only while its misalignment is below
// this fraction of the limit: well below where a held law ends, so that a contact just released
// is not held again at once.
constexpr double kSteadyCreepHold = 0.25;
// A contact released from its held law is not taken as sliding steadily along phi* again until
// its slip has grown this many times: just after its release its slip settles near phi* (lagging
// it by less than the held law's limit), is held again at once, and the held law and release
// alternate every few evaluations (found by fuzzing: a thousand contact changes at tolerance
// 1.6e-14, where the limit is tiny).
constexpr double kSteadyRearmGrowth = 10;
constexpr double kCreepTurnProbe = 1e-3;
// The turn (rad) over which lagShare differentiates the slip rate's turn about phi*: small against
// the curvature of r(d) over the circle, large against rounding of the rates (1e-16 relative).
constexpr double kLagProbeAngle_rad = 1e-5;
// A slipping contact whose slip stays below this multiple of the vanishing threshold for this many
// accepted steps has vanished: it lies within the integration's noise of zero and would only wander
// there (a slip that friction can barely hold decays very slowly). Taking it as zero moves the
// result by less than that multiple of the threshold.
constexpr double kStagnantSlipMultiple = 10;
constexpr int kStagnantSlipSteps = 50;
// A slipping contact whose slip is below this fraction of the regularizing slip is checked for
// steady sliding on the edge of its cone (see slidesSteadily).
constexpr double kSteadyCreepFraction = 0.1;
// A held contact whose cone could hold it again slips on (and its slip shrinks) only once its slip
// is this multiple of the vanishing threshold, so that contacts do not flicker on rounding.
constexpr double kReleaseSlipMultiple = 2;
// The first step after a held contact slips again covers this fraction of the impulse over which
// its small slip's direction turns (|u| / |du/dP|): about what the error control then accepts.
constexpr double kReleaseStepFraction = 0.5;
// Newton's method for phi*: the angle step of its numerical derivative (rad), the largest turn per
// iteration (rad), the convergence test (rad) and the iteration limit.
constexpr double kCreepAngleStep = 1e-6;
constexpr double kCreepMaxTurn = 0.5;
constexpr double kCreepAngleTolerance = 1e-10;
constexpr int kMaxCreepIterations = 30;
// A floor under |du/dP| (times M) that keeps phi*'s equation defined where the rate vanishes.
constexpr double kRateFloor = 1e-9;
// A held contact sticks only while its friction lies this fraction inside its cone (rounding in the
// stick solve): at the edge it slides, so that a located break takes effect where it is located.
constexpr double kConeSlackRelative = 1e-12;
// An event is located when its function is this small against its scale times the tolerance...
constexpr double kEventResidualFraction = 1e-4;
// ...or when the bracket on the step length is this many rounding units wide. A phase end missed
// by a correction shorter than this fraction of the trial step is reached by a second-order step
// from the trial's end, if that step's error estimate (Euler's, which bounds Heun's) stays below
// this fraction of the tolerance.
constexpr double kPolishStepFraction = 1e-3;
constexpr double kPolishErrorFraction = 1e-3;
constexpr double kEventBracketUlps = 8;
// A phase end predicted within the next step (extrapolated from the last accepted step) is
// aimed at: the step is cut to end there, and from where it ends, short or past by about 1e-4 of
// it, third-order steps land on it (Newton's method on their length). They may reach at most this
// fraction of the step away (beyond, the step counts as an ordinary one, or the event is located
// with trial steps), their embedded error must stay below the second fraction of the tolerance
// (so that they add nothing measurable to the step's error), and a few of them must land.
constexpr double kLandingShiftFraction = 1e-2;
constexpr double kLandingErrorFraction = 1e-2;
constexpr int kMaxLandingSteps = 3;
// The phase-end functions are sums of terms of their scale (v_y0, the compression work), so their
// rounding is a few units of that: at tolerances below about 3.6e-11 (the default among them)
// kEventResidualFraction asks for less than this many units, within which a landing counts as
// reached.
constexpr double kEventRoundingUlps = 16;
// An aimed step that does not land (rare: the prediction missed by more than
// kLandingShiftFraction) is followed by at most this many more before phase ends are located with
// trial steps again, until the next event or change (so that aiming never crawls toward the end).
constexpr int kMaxMissedLandings = 2;
// The smallest share of the impulse scale a step's error allowance is cut to (error per unit step):
// steps in the change of variable near a vanishing slip advance P very little and need no less.
// (Larger floors, 0.3 to 1, cost 3 to 10 % fewer evaluations but let rare impacts of the rolling
// bench set exceed 1e-9 V0 at the default tolerance.)
constexpr double kMinErrorShare = 0.2;
// A slipping slip below the regularizing slip that grows may change by at most this multiple of its
// own size in one step (so grow by at most 70 %, and turn by at most about 41 degrees). Near a slip
// that small (a nose slip growing again after passing close by zero) a longer step comes near the
// branch point of |u| for complex impulses, where the embedded error estimate fails: measured 5 to
// 30 times below the step's true error. Such steps made the largest errors of the bench's impacts
// on the pool cushion (at tolerance 3e-11: 9.0e-10 V0, 5.4e-10 with a bound of 1) and, with a bound
// of 1, of the impacts of play (1.1e-9 V0 over the 16,180 of `baize bench cushion --from-shots
// 5000`, a slip growing from 4.1e-4 to 7.7e-4 V in one step; 5.9e-10 with 0.7, for 1 % more
// evaluations there and 0.3 to 0.6 % on the bench's).
constexpr double kSmallSlipGrowthPerStep = 0.7;
// A step (in tau) may span at most this many time constants of the fastest-turning slip direction
// (slipDirectionStep). A small slip's direction settles where friction and the other forces
// balance at a rate that grows as 1 / (|u| + s0), and steps of more than about two of its time
// constants run toward the method's stability limit (about 6 on the real axis), where the embedded
// estimate missed steps' true errors by 10 to 100 times: a nose slip of 2 s0 with a large cloth
// slip left an impact 4.7e-9 V0 off, and grippy cushions (mu_s 0.35 to 0.425) missed 1e-9 V0 in
// 3 of 1000 impacts. Capping the step before it is taken also spares the rejections the controller
// made there: the impacts of play take 2.6 % fewer evaluations. Of the caps tried (1.5 to 5),
// 2.75 was the one with no impact above 1e-9 V0 on any set (docs/cushion.md, "Steps capped by a
// slip's turning").
constexpr double kSlipDirectionTimeConstants = 2.75;
// A step (in tau) may span at most this many of a slipping slip's turning scales |u| / |du/dtau|
// at its start (turningScaleStep): about the distance to the solution's nearest complex
// singularity, where the slip would vanish, and beyond it the embedded estimate is no guide. A
// nose slip passing 7e-4 m/s from zero (a quarter of s0) on a grippy cloth was crossed in one step
// of 1.2 turning scales, grown threefold after a step whose estimate read near zero; its estimate
// read 900 times below its true error, and the impact ended 1.7e-9 V0 off. With this cap none of
// 72,000 grippy impacts lies above 5e-10 V0 (5 did, the largest 9.7e-10), nor with caps of 0.8 to
// 1.25 any of 18,000 of them; 1.5 left 25 of the 72,000, 3 of them above 1e-9, and 0.5 costs 8 %
// more evaluations on the impacts of play (docs/cushion.md, "Steps capped at a slip's turning
// scale").
constexpr double kTurningScaleSteps = 1.0;
// Step-size control of the embedded pair: safety factor and bounds on the change per step.
constexpr double kStepSafety = 0.9;
constexpr double kStepMinFactor = 1.0 / 3;
constexpr double kStepMaxFactor = 3.0;
// The order with which the error estimate scales with the step (see stepFactor).
constexpr double kErrorOrder = 8;
// First step as a fraction of M v_y0, the scale of the whole normal impulse.
constexpr double kFirstStepFraction = 0.2;
// After a contact changes its law (held, released, stuck, slipping again) the next step covers at
// least this fraction of the first step's impulse: the step before was sized for the law that
// ended, often cut short to land on the change (to 1e-9 of the impulse where an approaching slip
// was landed on), and the controller grew it back threefold per step (kStepMaxFactor: 15 steps in
// one stick-slip impact of play). The step's bounds and the error control then apply as to any
// step. 1, 0.1 and 0.01 gave 381.0, 380.2 and 381.0 evaluations per impact of play (384.9
// without), the largest error at most 3.3e-10 V0 at each.
constexpr double kRestartStepFraction = 0.1;
// The slip rate counts as affine in the friction direction when r(-x) misses r0 - W x by at most
// this fraction of the rates' size (rounding), and vanishes along a direction (the cone's edge)
// when it is that small there; a closed-form root of phi*'s equation is kept when its residual is
// within the second fraction (rounding of the quartic's roots).
constexpr double kAffineCheckRelative = 1e-12;
constexpr double kAffineRootRelative = 1e-9;
// Samples on the circle when searching for the direction a contact slips off in from rest.
constexpr int kDirectionSamples = 72;
// The tolerances accepted: below 1e-14 the slips are not resolved in double precision. Above 1e-6
// the vanishing threshold (kVanishedSlipFraction x tolerance x velocity scale, 5e-6 V at 1e-6)
// comes within about two decades of the regularizing slip (kRegularizingSlipFraction), below which
// slips are resolved: with the threshold at 10 x tolerance x V, at 1e-4 the two met, contacts were
// held and released on every step, and a sixth of random impacts (rolling balls with sidespin) ran
// out of steps or contact changes.
constexpr double kMinTolerance = 1e-14;
constexpr double kMaxTolerance = 1e-6;
// Logic guards, far above what the bounded equations need (an impact takes tens of steps and a few
// contact changes).
constexpr int kMaxSteps = 100000;
constexpr int kMaxContactChanges = 1000;
constexpr int kMaxEventIterations = 60;

constexpr double kEpsilon = 2.220446049250313e-16;

// The Dormand-Prince 8(5,3) pair (Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed., section
// II.10): 12 stages, the last evaluation reused as the next step's first; error estimated from
// embedded 5th- and 3rd-order solutions.
namespace dp853 {
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
}  // namespace dp853

// At most `capacity` items without allocating: the step loop's events and the ones a step crossed
// (the phase end, and two for each held contact), built on every step. The items live in raw
// storage, constructed as they are pushed: value-initializing every slot on every step took about
// 1 % of a random shot's instructions.
template <typename T, int capacity>
class FixedList {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  FixedList() {}
  FixedList(const FixedList&) = delete;
  FixedList& operator=(const FixedList&) = delete;
  void push_back(const T& item) {
    if (count_ == capacity) throw std::logic_error("exact cushion solver: fixed list overflow");
    new (storage_ + count_ * sizeof(T)) T(item);
    ++count_;
  }
  int size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const T& operator[](int i) const { return begin()[i]; }
  // (std::launder only where an item lives: an empty list's storage holds none.)
  const T* begin() const {
    const T* first = reinterpret_cast<const T*>(storage_);
    return count_ > 0 ? std::launder(first) : first;
  }
  const T* end() const { return begin() + count_; }

 private:
  alignas(T) unsigned char storage_[capacity * sizeof(T)];
  int count_ = 0;
};
constexpr int kMaxStepEvents = 9;
// Room for the contact changes of most impacts at once: the two initial modes and up to six changes
// (grown one by one, their reallocations were a sixth of a random shot's allocations).
constexpr std::size_t kContactChangesReserved = 8;

double cross(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  return p.x() * q.y() - p.y() * q.x();
}

// x^(-1/8) within 0.21 %, for the step controller (which needs no more: its safety factor is
// 10 %). Three square roots and a division took about 60 cycles in the chain of dependent
// operations that runs from a step's error to the next step's first stage, at every step; this
// takes about 25. A double's bits read as an integer are about 2^52 (log2 x + 1023), so those of
// x^(-1/8) are about (1 + 1/8) 1023 2^52 less an eighth of x's (within 3 %), and one Newton step
// on y^-8 = x, y (9 - x y^8) / 8, leaves it within 0.41 % below (centred: 0.21 % either way).
// Integer and IEEE operations only: the same bits on every machine. x is kept within
// [1e-300, 1e300], where y^8 neither overflows nor underflows.
static_assert(kErrorOrder == 8, "inverseEighthRoot stands for the power -1 / kErrorOrder");
double inverseEighthRoot(double x) {
  x = std::clamp(x, 1e-300, 1e300);
  constexpr std::int64_t kOne = std::int64_t{1023} << 52;  // the bits of 1.0
  constexpr std::int64_t kCentre = std::int64_t{7} << 45;  // balances the first guess's error
  // 1/8 of the Newton step, times 1.00203: the step leaves the root up to 0.406 % low, never high,
  // so this centres the result's error.
  constexpr double kNewtonEighth = 0.125 * 1.00203;
  std::int64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::int64_t guess_bits = kOne + (kOne >> 3) - (bits >> 3) - kCentre;
  double y;
  std::memcpy(&y, &guess_bits, sizeof y);
  const double y2 = y * y, y4 = y2 * y2;
  return y * (9 - x * (y4 * y4)) * kNewtonEighth;
}

double stepFactor(double error) {
  if (error == 0) return kStepMaxFactor;
  if (!(error > 0)) return kStepMinFactor;  // NaN: that step failed; try a shorter one
  // The estimate is 8th order; most steps lie at the floor of the error share, where dividing by
  // the share leaves that order (above the floor it is one lower, which the safety factor covers).
  return std::clamp(kStepSafety * inverseEighthRoot(error), kStepMinFactor, kStepMaxFactor);
}

// The root in (0, limit] of the cubic through value g0 > 0 and slope d0 < 0 at 0 and value gp and
// slope dp at -H < 0 (an event function extrapolated from the last step across the next): Newton
// from the linear guess, kept where the cubic falls. Returns false when it finds none there.
bool extrapolatedRoot(double gp, double dp, double g0, double d0, double H, double limit,
                      double* root) {
  if (!(g0 > 0) || !(d0 < 0) || !(H > 0) || !(limit > 0)) return false;
  double t = -g0 / d0;
  if (!(t <= 2 * limit)) return false;  // far beyond the step: nothing to aim at yet
  const double b = (d0 + dp + 2 * (gp - g0) / H) / (H * H);
  const double a = ((gp - g0) / H + d0 + b * H * H) / H;
  for (int it = 0; it < 20; ++it) {
    const double value = g0 + t * (d0 + t * (a + t * b));
    const double slope = d0 + t * (2 * a + 3 * b * t);
    if (!(slope < 0)) return false;
    const double next = t - value / slope;
    if (!(next > 0)) return false;
    const bool converged = std::abs(next - t) <= 4 * kEpsilon * next;
    t = next;
    if (converged) break;
  }
  if (!(t <= limit)) return false;
  *root = t;
  return true;
}

// The root in (0, 1) of the cubic with values g0 > 0 and g1 <= 0 and slopes d0, d1 at 0 and 1
// (bisection safeguarded Newton; the cubic need not be monotone, the bracket keeps it in range).
double hermiteRoot(double g0, double d0, double g1, double d1) {
  auto value = [&](double t) {
    const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
    const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
    return h00 * g0 + h10 * d0 + h01 * g1 + h11 * d1;
  };
  double lo = 0, hi = 1, t = g0 / (g0 - g1);
  for (int it = 0; it < 40; ++it) {
    const double v = value(t);
    (v > 0 ? lo : hi) = t;
    const double slope = (value(t + 1e-7) - value(t - 1e-7)) / 2e-7;
    double next = slope != 0 ? t - v / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) < 1e-14) return next;
    t = next;
  }
  return t;
}

struct ContactState {
  bool frictionless = false;
  ContactMode mode = ContactMode::Slip;  // Stick: held (see the top of the file)
  Eigen::Vector2d direction =
      Eigen::Vector2d::UnitX();                      // slip direction for a slip of exactly zero
  Eigen::Vector2d creep = Eigen::Vector2d::UnitX();  // held: where to start looking for phi*
  // Held with a slip that started from zero (not a small slip caught sliding steadily): its slip
  // lags phi*, which turned from creep_origin since then (see lagCorrected).
  bool creep_from_rest = false;
  Eigen::Vector2d creep_origin = Eigen::Vector2d::UnitX();
  // How its slip grows from zero: as the impulse since then (1: held as it vanished, its cone not
  // holding it) or as its square (2: its cone held it until now, so its growth starts at zero).
  double creep_growth_order = 1;
  int small_slip_steps = 0;  // consecutive accepted steps with a slip below kStagnantSlipMultiple
  // m/s: released from its held law with a slip of a tenth of this; taken as sliding steadily
  // along phi* again only once its slip has grown to it (see kSteadyRearmGrowth).
  double steady_rearm_slip = 0;
  // Slipping and approaching zero along its line: runs in P (see kApproachEntry).
  bool approaching = false;
  // Its slip grows away from zero, above kRecedingSlipMultiple x s0: it runs in P (never together
  // with approaching; a slip that large is never held or released directly).
  bool receding = false;
  bool approach_blocked = false;  // left its line: not again until its mode changes
  Eigen::Vector2d approach_direction = Eigen::Vector2d::UnitX();  // its slip's line when it began
};

struct Friction {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  // at I, per unit P, along the slip
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  // at C, per unit P, along the slip
};

// Per contact: whether its friction follows the stick law, and otherwise its slip direction.
struct Laws {
  std::array<bool, 2> stick = {false, false};
  std::array<Eigen::Vector2d, 2> direction = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
};

struct Step {
  State z;
  State rate_at_end;  // FSAL: the rate at the step's end, reused as the next step's first stage
  double error = 0;   // scaled error norm; <= 1 accepts
  // (u_I, u_C) at z as slips() gives them, set by finishStep (read only for a main-loop step
  // accepted as it is: a step located or landed on may carry another step's).
  std::array<Eigen::Vector2d, 2> slips_at_end = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
};

class ExactImpact {
 public:
  ExactImpact(const CushionParams& params, const BallVelocity& incoming,
              const ExactSolverOptions& options)
      : params_(params), incoming_(incoming), options_(options) {
    result_.contact_changes.reserve(kContactChangesReserved);
    s_ = contactSinTheta(params);
    c_ = std::sqrt(1 - s_ * s_);
    M_ = params.mass_kg;
    inverse_mass_ = 1 / M_;
    mu_ = {params.cushion_friction, params.cloth_friction};
    slip0_ = {cushionSlip(params, incoming), clothSlip(params, incoming)};
    vy0_ = incoming.v.y();
    velocity_scale_ = incoming.v.norm() + params.radius_m * incoming.w.norm();
    const double impulse_scale = M_ * velocity_scale_;
    impulse_scale_ = impulse_scale;
    for (int i = 0; i < kWork; ++i) error_scale_[i] = options.tolerance * impulse_scale;
    error_scale_[kWork] = options.tolerance * impulse_scale * velocity_scale_;
    inverse_error_scale_ = error_scale_.cwiseInverse();
    vanished_slip_ = kVanishedSlipFraction * options.tolerance * velocity_scale_;
    regularizing_slip_ = kRegularizingSlipFraction * velocity_scale_;
    creep_error_limit_ = kCreepErrorFraction * options.tolerance * velocity_scale_;
    for (int k = 0; k < 2; ++k) contacts_[k].frictionless = mu_[k] == 0;
    coupling_x_ = 1 - 2.5 * s_;
    coupling_y_ = 2.5 - s_;
    diagonal_y_ = s_ * s_ + 2.5;
    scaled_ = {3.5 * inverse_mass_,         diagonal_y_ * inverse_mass_,
               coupling_x_ * inverse_mass_, coupling_y_ * inverse_mass_,
               s_ * c_ * inverse_mass_,     c_ * inverse_mass_};
    // See slipDirectionStep: the cloth's friction at its largest is mu_s (s + c mu_w). (A
    // frictionless contact never slips with friction: its bound is never read.)
    const std::array<double, 2> direction_rate = {
        3.5 * mu_[0] * inverse_mass_, 3.5 * (mu_[1] * (s_ + c_ * mu_[0])) * inverse_mass_};
    for (int k = 0; k < 2; ++k) {
      // (A rate of a subnormal friction coefficient would overflow the quotient.)
      direction_time_scale_[k] =
          direction_rate[k] > kSlipDirectionTimeConstants / std::numeric_limits<double>::max()
              ? kSlipDirectionTimeConstants / direction_rate[k]
              : std::numeric_limits<double>::infinity();
    }
  }

  CushionImpactResult run();

 private:
  bool slipping(int k) const {
    return !contacts_[k].frictionless && contacts_[k].mode == ContactMode::Slip;
  }
  bool held(int k) const {
    return !contacts_[k].frictionless && contacts_[k].mode == ContactMode::Stick;
  }
  // Whether held contact k follows the lag-corrected law (lagCorrected below): held from rest
  // while the other contact slides. Only then is its law accurate beyond a small slip; otherwise
  // (the other contact held too) the slip measured against s0 also ends it.
  bool lagCorrected(int k) const { return contacts_[k].creep_from_rest && !held(1 - k); }
  // Whether slipping contact k's factor |u| / (|u| + s0) is in sigma (not while it approaches or
  // recedes).
  bool regularized(int k) const {
    return slipping(k) && !contacts_[k].approaching && !contacts_[k].receding;
  }
  // The s0 of sliding contact k's factor |u| / (|u| + s0) in sigma: 0 while it recedes (factor 1).
  double factorSlip(int k) const { return contacts_[k].receding ? 0.0 : regularizing_slip_; }

  // The contact matrix (see the top of the file) times (a_x, a_y, b_x, b_y); half its entries are
  // 0.
  Eigen::Vector4d contactResponse(double ax, double ay, double bx, double by) const {
    return {3.5 * ax + coupling_x_ * bx, diagonal_y_ * ay + coupling_y_ * by,
            coupling_x_ * ax + 3.5 * bx, coupling_y_ * ay + 3.5 * by};
  }

  // Both slips at z: (u_I, u_C).
  std::array<Eigen::Vector2d, 2> slips(const State& z) const {
    const Eigen::Vector4d response = contactResponse(z[kAx], z[kAy], z[kBx], z[kBy]);
    return {
        Eigen::Vector2d(slip0_[0] - Eigen::Vector2d(response[0], response[1] - s_ * c_ * z[kP]) *
                                        inverse_mass_),
        Eigen::Vector2d(slip0_[1] -
                        Eigen::Vector2d(response[2], response[3] + c_ * z[kP]) * inverse_mass_)};
  }
  Eigen::Vector2d slip(int k, const State& z) const { return slips(z)[k]; }

  template <typename Vector>  // State, or Extended
  double normalVelocity(const Vector& z) const {
    return vy0_ - (c_ * z[kP] - s_ * z[kAy] + z[kBy]) * inverse_mass_;
  }

  // Friction per unit P under the given laws (a contact with a zero direction has no friction).
  Friction frictionFor(const Laws& laws) const {
    const double s = s_, c = c_;
    const bool stick_I = !contacts_[0].frictionless && laws.stick[0];
    const bool stick_C = !contacts_[1].frictionless && laws.stick[1];
    const Eigen::Vector2d slide_I =
        contacts_[0].frictionless ? Eigen::Vector2d::Zero() : laws.direction[0];
    const Eigen::Vector2d slide_C =
        contacts_[1].frictionless ? Eigen::Vector2d::Zero() : laws.direction[1];
    Friction f;
    if (stick_I && stick_C) {  // the x pair gives 0, the y pair a 2x2 solve
      const double det = 3.5 * (s * s + 2.5) - (2.5 - s) * (2.5 - s);
      f.a.y() = c * (2.5 + 2.5 * s) / det;
      f.b.y() = -f.a.y();
    } else if (stick_I) {  // the cloth slides; its force couples through q = s + c a_y
      const Eigen::Vector2d g = mu_[1] * slide_C;
      f.a.y() = (s * c - (2.5 - s) * s * g.y()) / ((s * s + 2.5) + (2.5 - s) * c * g.y());
      const double table_rate = s + c * f.a.y();
      f.a.x() = -(1 - 2.5 * s) * table_rate * g.x() * (1 / 3.5);
      f.b = table_rate * g;
    } else {
      f.a = mu_[0] * slide_I;
      if (stick_C) {
        f.b = Eigen::Vector2d(-(1 - 2.5 * s) * f.a.x() * (1 / 3.5),
                              -(c + (2.5 - s) * f.a.y()) * (1 / 3.5));
      } else {
        f.b = mu_[1] * (s + c * f.a.y()) * slide_C;
      }
    }
    return f;
  }

  // d(slip_k)/dP under friction f.
  Eigen::Vector2d slipRate(int k, const Friction& f) const {
    const Eigen::Vector4d response = contactResponse(f.a.x(), f.a.y(), f.b.x(), f.b.y());
    if (k == 0) return -Eigen::Vector2d(response[0], response[1] - s_ * c_) * inverse_mass_;
    return -Eigen::Vector2d(response[2], response[3] + c_) * inverse_mass_;
  }

  // How far inside its friction cone contact k's friction is, as a fraction of the cone.
  double coneMargin(int k, const Friction& f) const {
    if (k == 0) return 1 - f.a.norm() / mu_[0];
    return 1 - f.b.norm() / (mu_[1] * (s_ + c_ * f.a.y()));
  }

  // phi* of the cloth contact while the cushion contact slides (or is frictionless), in closed
  // form: the cushion's friction a then does not depend on the cloth's direction d, and the cloth's
  // own friction mu_s q d (q = s + c a_y) enters its slip rate isotropically, du_C/dP = r0 - k d
  // with k = 7/2 mu_s q / M. So phi* = r0 / |r0|, along which the slip grows at |r0| - k (the cone
  // cannot hold the contact exactly when |r0| > k). This is the held contact of every rolling or
  // nearly rolling ball, the common case. Returns false when it does not apply.
  bool clothCreepDirection(int k, const Laws& laws, Eigen::Vector2d* result) const {
    if (k != 1 || laws.stick[0]) return false;
    const ClothDrive drive = clothDrive(laws);
    const double size = drive.rate.norm();
    if (!(size > drive.own)) return false;
    *result = drive.rate / size;
    return true;
  }

  // The cloth's slip rate r0 without its own friction, and k, while the nose slides along
  // laws.direction[0] (or is frictionless); see clothCreepDirection.
  struct ClothDrive {
    Eigen::Vector2d rate;  // r0, m/s per N s
    double own = 0;        // k, m/s per N s
  };
  ClothDrive clothDrive(const Laws& laws) const {
    const Eigen::Vector2d a = contacts_[0].frictionless
                                  ? Eigen::Vector2d::Zero()
                                  : Eigen::Vector2d(mu_[0] * laws.direction[0]);
    return {Eigen::Vector2d(-coupling_x_ * a.x() * inverse_mass_,
                            -(c_ + coupling_y_ * a.y()) * inverse_mass_),
            3.5 * mu_[1] * (s_ + c_ * a.y()) * inverse_mass_};
  }

  // The direction phi* a held contact k slides along when its cone cannot hold it: the slip it then
  // makes grows along phi* (cross(phi*, du_k/dP) = 0 with du_k/dP . phi* > 0). Newton on the angle
  // from `guess`; returns false if that does not converge to such a direction.
  bool creepDirection(int k, Laws laws, const Eigen::Vector2d& guess,
                      Eigen::Vector2d* result) const {
    if (clothCreepDirection(k, laws, result)) return true;
    const AffineNewton affine = creepDirectionAffineNewton(k, laws, guess, result);
    if (affine != AffineNewton::NotAffine) return affine == AffineNewton::Found;
    laws.stick[k] = false;
    auto turn = [&](double phi, double* growth) {
      laws.direction[k] = Eigen::Vector2d(std::cos(phi), std::sin(phi));
      const Eigen::Vector2d r = slipRate(k, frictionFor(laws));
      *growth = r.dot(laws.direction[k]);
      return cross(laws.direction[k], r) / (r.norm() + kRateFloor * inverse_mass_);
    };
    // Secant iterations, started with a difference over a small angle: one evaluation of the
    // rate per iteration (a central difference takes three), converging almost as fast from the
    // close guesses it is given (the last phi*).
    double phi = std::atan2(guess.y(), guess.x()), growth = 0;
    double value = turn(phi, &growth);
    double previous_phi = phi + kCreepAngleStep, previous_growth = 0;
    double previous_value = turn(previous_phi, &previous_growth);
    for (int it = 0; it < kMaxCreepIterations; ++it) {
      const double slope = (value - previous_value) / (phi - previous_phi);
      if (!(slope != 0)) break;
      const double change = std::clamp(-value / slope, -kCreepMaxTurn, kCreepMaxTurn);
      previous_phi = phi;
      previous_value = value;
      phi += change;
      value = turn(phi, &growth);
      if (std::abs(change) <= kCreepAngleTolerance) {
        if (!(growth > 0)) return false;
        *result = Eigen::Vector2d(std::cos(phi), std::sin(phi));
        return true;
      }
    }
    return false;
  }

  // Contact k's slip rate as r(d) = r0 + W d in its sliding direction d, from the rates at d = 0,
  // x and y; false when it is not affine (the rate at -x misses r0 - W x by more than rounding).
  bool affineSlipRate(int k, Laws laws, Eigen::Vector2d* r0, Eigen::Matrix2d* W) const {
    laws.stick[k] = false;
    auto rateAlong = [&](const Eigen::Vector2d& d) {
      laws.direction[k] = d;
      return slipRate(k, frictionFor(laws));
    };
    *r0 = rateAlong(Eigen::Vector2d::Zero());
    W->col(0) = rateAlong(Eigen::Vector2d::UnitX()) - *r0;
    W->col(1) = rateAlong(Eigen::Vector2d::UnitY()) - *r0;
    const Eigen::Vector2d check = rateAlong(-Eigen::Vector2d::UnitX());
    return (check - (*r0 - W->col(0))).norm() <=
           kAffineCheckRelative * (r0->norm() + W->col(0).norm());
  }

  // phi* by Newton's method when the slip rate is affine in the friction direction d, r(d) = r0 +
  // W d (the nose's, whether the cloth slides or sticks): the turn cross(d, r(d)) and its slope in
  // the angle, cross(d', r(d)) + cross(d, W d') with d' = d turned a right angle, are exact from r0
  // and W, so an iteration costs no rate evaluation and no sine or cosine (d is turned by
  // normalizing d + dphi d'). NotAffine when r is not affine here (affineSlipRate); NotFound when
  // Newton does not reach a direction along which the slip grows, or, on the cone's edge, along
  // which its rate vanishes.
  enum class AffineNewton { Found, NotFound, NotAffine };
  AffineNewton creepDirectionAffineNewton(int k, Laws laws, const Eigen::Vector2d& guess,
                                          Eigen::Vector2d* result) const {
    if (k != 0) return AffineNewton::NotAffine;  // the cloth's is rational while the nose sticks
    Eigen::Vector2d r0;
    Eigen::Matrix2d W;
    if (!affineSlipRate(k, laws, &r0, &W)) return AffineNewton::NotAffine;
    return affineNewton(r0, W, guess, result) ? AffineNewton::Found : AffineNewton::NotFound;
  }
  // The Newton iterations of creepDirectionAffineNewton on r(d) = r0 + W d from `guess`.
  static bool affineNewton(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                           const Eigen::Vector2d& guess, Eigen::Vector2d* result) {
    Eigen::Vector2d d = guess.normalized();
    for (int it = 0; it < kMaxCreepIterations; ++it) {
      const Eigen::Vector2d r = r0 + W * d, across(-d.y(), d.x());
      const double slope = cross(across, r) + cross(d, W * across);
      if (!(slope != 0)) break;
      const double change = std::clamp(-cross(d, r) / slope, -kCreepMaxTurn, kCreepMaxTurn);
      d = (d + change * across).normalized();
      if (std::abs(change) <= kCreepAngleTolerance) {
        // On the cone's edge the slip rate vanishes along phi* (the friction there is what
        // sticking needs): its growth is zero up to rounding, of either sign, and the root is the
        // answer (lawsAt slides the held contact along it; slidesSteadily takes a slip lying along
        // it as sliding steadily on the edge). Refused, it sent lawsAt on to a search of the whole
        // circle, dozens of times the cost (a third of the time of an impact that grazes the edge
        // for long).
        const Eigen::Vector2d rate = r0 + W * d;
        const double scale = r0.norm() + W.col(0).norm() + W.col(1).norm();
        const bool on_edge = rate.norm() <= kAffineCheckRelative * scale;
        if (!(rate.dot(d) > 0) && !on_edge) break;
        *result = d;
        return true;
      }
    }
    return false;
  }

  // phi* in closed form when the slip rate is affine in the friction direction d, r(d) = r0 + W d
  // (the other contact slides or is frictionless; with it stuck its stick law makes r rational):
  // cross(d, r0 + W d) = 0 is then A cos + B sin + C cos 2phi + D sin 2phi + E = 0, a quartic in
  // t = tan(phi / 2). Returns false when r is not affine or no root has the slip growing.
  bool creepDirectionAffine(int k, Laws laws, Eigen::Vector2d* result) const {
    Eigen::Vector2d r0;
    Eigen::Matrix2d W;
    if (!affineSlipRate(k, laws, &r0, &W)) return false;
    const Eigen::Vector2d wx = W.col(0), wy = W.col(1);
    const double W00 = wx.x(), W10 = wx.y(), W01 = wy.x(), W11 = wy.y();
    const physics::PolynomialCoefficients quartic = {r0.y() + W10, -2 * r0.x() + 2 * (W11 - W00),
                                                     -2 * W10 - 4 * W01,
                                                     -2 * r0.x() - 2 * (W11 - W00), -r0.y() + W10};
    std::vector<double> angles;
    for (double t : physics::realRoots(quartic)) angles.push_back(2 * std::atan(t));
    angles.push_back(M_PI);  // t = infinity: a root when the quartic's leading term vanishes
    double best_growth = 0;
    for (double phi : angles) {
      const Eigen::Vector2d d(std::cos(phi), std::sin(phi));
      const Eigen::Vector2d r = r0 + wx * d.x() + wy * d.y();
      if (std::abs(cross(d, r)) > kAffineRootRelative * (r0.norm() + wx.norm() + wy.norm()))
        continue;
      if (r.dot(d) > best_growth) {
        best_growth = r.dot(d);
        *result = d;
      }
    }
    return best_growth > 0;
  }

  // The same by a search over the whole circle (robust, for a first guess): of the directions along
  // which the slip grows along itself, the one where it grows fastest.
  Eigen::Vector2d creepDirectionSearch(int k, Laws laws) const {
    laws.stick[k] = false;
    // The cloth contact while the nose slides: r0 / |r0| (clothCreepDirection), also where its cone
    // holds it (then no direction grows, and the search below ends on the same r0 / |r0|).
    if (k == 1 && !laws.stick[0]) {
      const Eigen::Vector2d r0 = clothDrive(laws).rate;
      if (r0.norm() > 0) return r0.normalized();
    }
    Eigen::Vector2d solved = Eigen::Vector2d::Zero();  // set whenever a closed form applies
    if (creepDirectionAffine(k, laws, &solved)) return solved;
    auto rateAlong = [&](double phi) {
      laws.direction[k] = Eigen::Vector2d(std::cos(phi), std::sin(phi));
      return slipRate(k, frictionFor(laws));
    };
    auto turn = [&](double phi) {
      return cross(Eigen::Vector2d(std::cos(phi), std::sin(phi)), rateAlong(phi));
    };
    const double spacing = 2 * M_PI / kDirectionSamples;
    std::array<double, kDirectionSamples + 1> turns;
    for (int i = 0; i <= kDirectionSamples; ++i) turns[i] = turn(i * spacing);
    double best_growth = 0, best_phi = 0;
    for (int i = 0; i < kDirectionSamples; ++i) {
      if ((turns[i] <= 0) == (turns[i + 1] <= 0)) continue;
      double lo = i * spacing, hi = (i + 1) * spacing;
      const bool lo_negative = turns[i] <= 0;
      for (int it = 0; it < 60 && hi - lo > 4 * kEpsilon; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((turn(mid) <= 0) == lo_negative ? lo : hi) = mid;
      }
      const double phi = 0.5 * (lo + hi);
      const double growth = rateAlong(phi).dot(Eigen::Vector2d(std::cos(phi), std::sin(phi)));
      if (growth > best_growth) {
        best_growth = growth;
        best_phi = phi;
      }
    }
    if (best_growth > 0) return Eigen::Vector2d(std::cos(best_phi), std::sin(best_phi));
    // None (not expected: the contact matrix is positive definite): along the rate it would get.
    const Eigen::Vector2d r = rateAlong(0) + rateAlong(M_PI);
    return r.norm() > 0 ? Eigen::Vector2d(r.normalized()) : Eigen::Vector2d::UnitX();
  }

  // lawsAt's most common case written out (a rolling ball's cloth contact, held while the cushion
  // contact slides or is frictionless): the stick friction the cloth would need is M r0 / (7/2) and
  // its cone is mu_s q, so it sticks while |r0| <= k and otherwise slides along phi* = r0 / |r0|
  // (see clothCreepDirection). False (laws untouched) within rounding of the cone's edge, which
  // the general path settles.
  bool clothHeldLaws(Laws* laws) const {
    const ClothDrive drive = clothDrive(*laws);
    const Eigen::Vector2d& r0 = drive.rate;
    const double own = drive.own;
    const double size = r0.norm();
    if (1 - size / own >= kConeSlackRelative) return true;  // the cone holds it: it sticks
    if (!(size > own)) return false;
    laws->stick[1] = false;
    laws->direction[1] = r0 / size;
    if (contacts_[1].creep_from_rest) {
      laws->direction[1] =
          lagCorrected(contacts_[1].creep_origin, laws->direction[1],
                       size / ((size - own) / contacts_[1].creep_growth_order + size));
    }
    return true;
  }

  // The share of phi*'s turn since its slip was zero that held contact k's slip follows (see
  // lagCorrected), for any slip rate r(d): near phi* the slip's direction theta turns at
  // d theta/dP = -kappa (theta - phi*) / |u| with kappa = -d cross(d, r(d)) / d theta at phi*, and
  // with |u| = g (P - P0) and phi* turning steadily the slip follows the share kappa / (g + kappa),
  // g = r(phi*) . phi* its growth. A slip that starts where the cone stops holding it grows from a
  // zero rate, |u| ~ (P - P0)^2, and lags half as much: kappa / (g / 2 + kappa) to first order
  // (creep_growth_order). (For the cloth, kappa = |r0| and g = |r0| - k: clothHeldLaws.) 1 (no
  // correction) where no slip grows along phi*.
  double lagShare(int k, Laws laws, const Eigen::Vector2d& phi) const {
    laws.stick[k] = false;
    laws.direction[k] = phi;
    const double growth = slipRate(k, frictionFor(laws)).dot(phi);
    const Eigen::Vector2d turned = probeTurned(phi);
    laws.direction[k] = turned;
    const double restoring = -cross(turned, slipRate(k, frictionFor(laws))) / kLagProbeAngle_rad;
    return lagShareOf(growth, restoring, contacts_[k].creep_growth_order);
  }
  // phi turned by kLagProbeAngle_rad.
  static Eigen::Vector2d probeTurned(const Eigen::Vector2d& phi) {
    const double cos_probe = std::cos(kLagProbeAngle_rad), sin_probe = std::sin(kLagProbeAngle_rad);
    return {phi.x() * cos_probe - phi.y() * sin_probe, phi.x() * sin_probe + phi.y() * cos_probe};
  }
  // The share from the slip's growth along phi* and the restoring rate of its direction.
  static double lagShareOf(double growth, double restoring, double growth_order) {
    if (!(growth > 0) || !(restoring > 0)) return 1;
    return restoring / (growth / growth_order + restoring);
  }
  // lagShare for the nose, whose slip rate is affine in its friction direction, r(d) = r0 + W d.
  static double affineLagShare(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                               const Eigen::Vector2d& phi, double growth_order) {
    const double growth = (r0 + W * phi).dot(phi);
    const Eigen::Vector2d turned = probeTurned(phi);
    const double restoring = -cross(turned, r0 + W * turned) / kLagProbeAngle_rad;
    return lagShareOf(growth, restoring, growth_order);
  }

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

  // The laws in force at slips u: slipping contacts slide along their slips; held contacts stick if
  // their cones can hold them and otherwise slide along phi* (found from their `creep` guesses).
  // When both are held and the friction that sticks both lies outside both cones, one slides first
  // (slidesFirst) and the other's cone is judged again against that: it may hold it then (a rolling
  // ball's cloth caught sliding steadily on its cone's edge while the nose sticks). Letting both
  // slide at once there let a stuck nose slip, its slip grown from zero to 3e-4 V in one step
  // without an event, 1.6e-7 V0 off the converged solution (a grippy impact).
  Laws lawsAt(const std::array<Eigen::Vector2d, 2>& u, std::array<double, 2>* speed) const {
    Laws laws;
    for (int k = 0; k < 2; ++k) {
      const double size = u[k].norm();
      if (speed) (*speed)[k] = size;
      laws.stick[k] = held(k);
      laws.direction[k] = contacts_[k].approaching ? contacts_[k].approach_direction
                          : size > 0               ? Eigen::Vector2d(u[k] / size)
                                                   : contacts_[k].direction;
    }
    if (!held(0) && !held(1)) return laws;
    if (held(1) && !held(0) && clothHeldLaws(&laws)) return laws;
    for (int round = 0; round < 2; ++round) {
      const int k = slidesFirst(laws, frictionFor(laws), u);
      if (k < 0) break;
      slideAlongCreep(k, &laws);
    }
    return laws;
  }

  // Of the held contacts that stick under `laws`, the one whose cone cannot hold friction f and
  // that slides first; -1 if every such cone holds. With both outside: the one that still slips
  // (caught sliding steadily, its slip above the vanishing threshold) while the other's slip is
  // zero, so that a moving contact goes on moving and a stuck one stays stuck as far as the cones
  // allow; otherwise the one whose cone is exceeded more (NaN counts as outside, ties the nose).
  int slidesFirst(const Laws& laws, const Friction& f,
                  const std::array<Eigen::Vector2d, 2>& u) const {
    std::array<bool, 2> outside = {false, false};
    std::array<double, 2> margin = {0, 0};
    for (int k = 0; k < 2; ++k) {
      if (!laws.stick[k] || !held(k)) continue;
      margin[k] = coneMargin(k, f);
      outside[k] = !(margin[k] >= kConeSlackRelative);
    }
    if (!outside[0] || !outside[1]) return outside[0] ? 0 : outside[1] ? 1 : -1;
    const bool moving_I = u[0].norm() > vanished_slip_, moving_C = u[1].norm() > vanished_slip_;
    if (moving_I != moving_C) return moving_I ? 0 : 1;
    return std::isnan(margin[1]) || margin[1] < margin[0] ? 1 : 0;
  }

  // Held contact k's law set to sliding along its phi* under the other contact's law in `laws`.
  void slideAlongCreep(int k, Laws* laws) const {
    Eigen::Vector2d phi;
    if (!creepDirection(k, *laws, contacts_[k].creep, &phi)) phi = creepDirectionSearch(k, *laws);
    if (lagCorrected(k))
      phi = lagCorrected(contacts_[k].creep_origin, phi, lagShare(k, *laws, phi));
    laws->stick[k] = false;
    laws->direction[k] = phi;
  }

  // Whether both contacts slip with friction along their slips (neither held nor approaching):
  // most of every impact, with its own rate (bothSlidingRate).
  bool bothSliding() const {
    return slipping(0) && slipping(1) && !contacts_[0].approaching && !contacts_[1].approaching;
  }

  // Whether the cloth contact is held while the nose slides with friction along its slip: the
  // common held case (a rolling ball's cloth contact), with its own rate (clothHeldRate).
  bool clothHeldWhileNoseSlides() const {
    return held(1) && slipping(0) && !contacts_[0].approaching;
  }

  // dz/dtau.
  State rate(const State& z) {
    if (bothSliding()) return bothSlidingRate(z);
    if (clothHeldWhileNoseSlides())
      return clothHeldRate(withSlips(z), normalVelocity(z)).head<kStateSize>();
    if (noseHeldWhileClothSlides())
      return noseHeldRate(withSlips(z), normalVelocity(z)).head<kStateSize>();
    return generalRate(z);
  }

  // rate() under the general laws (lawsAt).
  State generalRate(const State& z) {
    ++evaluations_;
    if (!held(0) && !held(1)) return slidingRate(z);
    std::array<double, 2> speed;
    const Laws laws = lawsAt(slips(z), &speed);
    const Friction f = frictionFor(laws);
    double sigma = 1;  // dP/dtau
    for (int k = 0; k < 2; ++k) {
      if (regularized(k)) sigma *= speed[k] / (speed[k] + regularizing_slip_);
    }
    State r;
    r << 1, f.a.x(), f.a.y(), f.b.x(), f.b.y(), c_ * normalVelocity(z);
    return sigma * r;
  }

  // Whether the nose contact is held while the cloth slides with friction along its slip.
  bool noseHeldWhileClothSlides() const {
    return held(0) && slipping(1) && !contacts_[1].approaching;
  }

  // rate() while the nose is held and the cloth slides (noseHeldWhileClothSlides), at the slips
  // held in y: the general laws written out for this case. The nose sticks while its stick law's
  // friction lies inside its cone (compared squared), and otherwise slides along phi*, found by
  // Newton's method on its slip rate, which is affine in its direction d: r(d) = r0 + W d with,
  // per unit P and the cloth's friction mu_s (s + c mu_w d_y) along d_C,
  //   r0 = -(1/M) ((1 - 5s/2) mu_s s d_Cx, (5/2 - s) mu_s s d_Cy - s c),
  //   W = -(mu_w/M) [7/2, (1 - 5s/2) mu_s c d_Cx; 0, s^2 + 5/2 + (5/2 - s) mu_s c d_Cy];
  // lag-corrected as lagShare says. The general laws serve an exactly zero cloth slip and a phi*
  // that Newton does not find.
  [[gnu::always_inline]] Extended noseHeldRate(const Extended& y, double vy) {
    const SlidingSlip cloth_slip = slidingSlip(y, 1);
    if (!(cloth_slip.speed > 0)) return generalExtendedRate(y);
    const double speed_C = cloth_slip.speed, inverse = cloth_slip.inverse;
    const double dCx = cloth_slip.x, dCy = cloth_slip.y;
    // The nose's stick law under the sliding cloth (frictionFor).
    const double gx = mu_[1] * dCx, gy = mu_[1] * dCy;
    double ay = (s_ * c_ - coupling_y_ * s_ * gy) / (diagonal_y_ + coupling_y_ * c_ * gy);
    double ax = -coupling_x_ * (s_ + c_ * ay) * gx * (1 / 3.5);
    const double hold_limit = mu_[0] * (1 - kConeSlackRelative);
    if (!(ax * ax + ay * ay <= hold_limit * hold_limit)) {
      const double nose = mu_[0] * inverse_mass_, cloth = mu_[1] * inverse_mass_;
      const Eigen::Vector2d r0(-coupling_x_ * cloth * s_ * dCx,
                               -(coupling_y_ * cloth * s_ * dCy - s_ * c_ * inverse_mass_));
      Eigen::Matrix2d W;
      W << -3.5 * nose, -coupling_x_ * cloth * c_ * mu_[0] * dCx, 0,
          -(diagonal_y_ * nose + coupling_y_ * cloth * c_ * mu_[0] * dCy);
      Eigen::Vector2d phi;
      if (!affineNewton(r0, W, contacts_[0].creep, &phi)) return generalExtendedRate(y);
      if (lagCorrected(0)) {
        phi = lagCorrected(contacts_[0].creep_origin, phi,
                           affineLagShare(r0, W, phi, contacts_[0].creep_growth_order));
      }
      ax = mu_[0] * phi.x();
      ay = mu_[0] * phi.y();
    }
    ++evaluations_;
    const double limit = mu_[1] * (s_ + c_ * ay);
    return scaledRate(speed_C * inverse, ax, ay, limit * dCx, limit * dCy, vy);
  }

  // The size of sliding contact k's slip held in y, its direction (x, y) and the inverse in sigma's
  // factor for it, |u| / (|u| + s0): what the held rates need of the contact that slides. Only the
  // size when it is not positive (the general laws then serve).
  struct SlidingSlip {
    double speed = 0, x = 0, y = 0, inverse = 0;
  };
  [[gnu::always_inline]] SlidingSlip slidingSlip(const Extended& y, int k) const {
    const double ux = y[kUIx + 2 * k], uy = y[kUIy + 2 * k];
    SlidingSlip slip;
    slip.speed = std::sqrt(ux * ux + uy * uy);
    if (!(slip.speed > 0)) return slip;
    const double to_direction = 1 / slip.speed;
    slip.inverse = 1 / (slip.speed + factorSlip(k));
    slip.x = ux * to_direction;
    slip.y = uy * to_direction;
    return slip;
  }
  // The general laws' rate with the slips' rates, where a held rate does not apply.
  Extended generalExtendedRate(const Extended& y) {
    return withSlipRates(generalRate(y.head<kStateSize>()));
  }

  // The rate sigma (1, a_x, a_y, b_x, b_y, c v_y) with the slips' rates (slipRatesOf).
  [[gnu::always_inline]] Extended scaledRate(double sigma, double ax, double ay, double bx,
                                             double by, double vy) const {
    Extended r;
    r[kP] = sigma;
    r[kAx] = ax * sigma;
    r[kAy] = ay * sigma;
    r[kBx] = bx * sigma;
    r[kBy] = by * sigma;
    r[kWork] = (c_ * vy) * sigma;
    r.tail<4>() = slipRatesOf(r[kP], r[kAx], r[kAy], r[kBx], r[kBy]);
    return r;
  }

  // rate() while the cloth is held and the nose slides (clothHeldWhileNoseSlides), at the slips
  // held in y: the laws of clothHeldLaws written out, so that the stages need neither the contact
  // matrix nor the general laws. The cloth sticks while its drive r0 lies inside its cone (|r0| <=
  // k, compared squared) and otherwise slides along r0, or, lag-corrected, along
  // (|r0| - k) / order x origin + r0, the direction of lagCorrected's blend. The general laws
  // serve an exactly zero nose slip and a drive on the cone's edge.
  [[gnu::always_inline]] Extended clothHeldRate(const Extended& y, double vy) {
    const SlidingSlip nose_slip = slidingSlip(y, 0);
    if (!(nose_slip.speed > 0)) return generalExtendedRate(y);
    const double speed_I = nose_slip.speed, inverse = nose_slip.inverse;
    const double ax = mu_[0] * nose_slip.x, ay = mu_[0] * nose_slip.y;
    const double own = 3.5 * mu_[1] * (s_ + c_ * ay) * inverse_mass_;  // k
    if (!(own > 0)) return generalExtendedRate(y);
    const double r0x = -coupling_x_ * ax * inverse_mass_;
    const double r0y = -(c_ + coupling_y_ * ay) * inverse_mass_;
    const double drive_squared = r0x * r0x + r0y * r0y;
    const double hold_limit = own * (1 - kConeSlackRelative);
    double bx, by;
    if (drive_squared <= hold_limit * hold_limit) {  // the cone holds it: the stick law
      bx = -coupling_x_ * ax * (1 / 3.5);
      by = -(c_ + coupling_y_ * ay) * (1 / 3.5);
    } else {
      const double drive = std::sqrt(drive_squared);
      if (!(drive > own)) return generalExtendedRate(y);
      double dx = r0x, dy = r0y;
      const ContactState& cloth = contacts_[1];
      if (cloth.creep_from_rest) {
        const double lag = (drive - own) / cloth.creep_growth_order;
        dx += lag * cloth.creep_origin.x();
        dy += lag * cloth.creep_origin.y();
      }
      const double limit = mu_[1] * (s_ + c_ * ay) / std::sqrt(dx * dx + dy * dy);
      bx = limit * dx;
      by = limit * dy;
    }
    ++evaluations_;
    return scaledRate(speed_I * inverse, ax, ay, bx, by, vy);
  }

  // rate() while both contacts slide (bothSliding), with the speeds cancelled out of it: with d =
  // (|u_I| + s0)(|u_C| + s0), sigma = |u_I| |u_C| / d, the nose's friction rate sigma mu_w u_I /
  // |u_I| = (mu_w |u_C| / d) u_I and the cloth's sigma mu_s q u_C / |u_C| with q = s + c mu_w
  // u_Iy / |u_I| is (mu_s (s |u_I| + c mu_w u_Iy) / d) u_C: one division, none by a speed. A
  // receding slip's s0 is taken as 0 (its factor in sigma is 1); at 5 s0 or more it keeps d from 0.
  State bothSlidingRate(const State& z) {
    return bothSlidingRate(withSlips(z), normalVelocity(z)).head<kStateSize>();
  }

  // The same at the slips held in y (see Extended) and normal velocity v_y, with the slips' own
  // rates: each rate is its numerator times the one inverse, so that the slips' rates are ready as
  // soon as the rest and the stages need no contact matrix between them (the stages run one after
  // another, each on the one before, and the dependent operations between them set the cost).
  [[gnu::always_inline]] Extended bothSlidingRate(const Extended& y, double vy) {
    ++evaluations_;
    const double uIx = y[kUIx], uIy = y[kUIy], uCx = y[kUCx], uCy = y[kUCy];
    const double speed_I = std::sqrt(uIx * uIx + uIy * uIy);
    const double speed_C = std::sqrt(uCx * uCx + uCy * uCy);
    const double inverse = 1 / ((speed_I + factorSlip(0)) * (speed_C + factorSlip(1)));
    const double nose = mu_[0] * speed_C;
    const double cloth = mu_[1] * (s_ * speed_I + c_ * mu_[0] * uIy);
    const double sliding = speed_I * speed_C;
    const double ax = nose * uIx, ay = nose * uIy, bx = cloth * uCx, by = cloth * uCy;
    const Eigen::Vector4d slip_rates = slipRatesOf(sliding, ax, ay, bx, by);
    Extended r;
    r[kP] = sliding * inverse;
    r[kAx] = ax * inverse;
    r[kAy] = ay * inverse;
    r[kBx] = bx * inverse;
    r[kBy] = by * inverse;
    r[kWork] = (sliding * (c_ * vy)) * inverse;
    r.tail<4>() = slip_rates * inverse;
    return r;
  }

  // du/dtau = (du_I, du_C) under the rate dz/dtau = (p, ax, ay, bx, by, .) (slipChanges, from the
  // contact matrix scaled as the stages' rate uses it).
  Eigen::Vector4d slipRatesOf(double p, double ax, double ay, double bx, double by) const {
    const ScaledContactMatrix& m = scaled_;
    return {-(m.diagonal_x * ax + m.coupling_x * bx),
            m.sin_cos * p - (m.diagonal_y * ay + m.coupling_y * by),
            -(m.coupling_x * ax + m.diagonal_x * bx),
            -(m.cos * p + (m.coupling_y * ay + m.diagonal_x * by))};
  }

  // z with its slips appended, and a rate with the slips' rates.
  Extended withSlips(const State& z) const {
    const std::array<Eigen::Vector2d, 2> u = slips(z);
    Extended y;
    y << z, u[0], u[1];
    return y;
  }
  Extended withSlipRates(const State& r) const {
    Extended y;
    y << r, slipRatesOf(r[kP], r[kAx], r[kAy], r[kBx], r[kBy]);
    return y;
  }

  // rate() when no contact is held (most of every impact), written out: the same equations as
  // slips(), frictionFor() and the change of variable, without the general laws' bookkeeping.
  State slidingRate(const State& z) const {
    const double P = z[kP], ax = z[kAx], ay = z[kAy], bx = z[kBx], by = z[kBy];
    double sigma_numerator = 1, sigma_denominator = 1, fax = 0, fay = 0, fbx = 0, fby = 0;
    if (slipping(0)) {
      const double ux = slip0_[0].x() - (3.5 * ax + coupling_x_ * bx) * inverse_mass_;
      const double uy =
          slip0_[0].y() - (diagonal_y_ * ay + coupling_y_ * by - s_ * c_ * P) * inverse_mass_;
      const double speed = std::sqrt(ux * ux + uy * uy);
      if (contacts_[0].approaching) {
        fax = mu_[0] * contacts_[0].approach_direction.x();
        fay = mu_[0] * contacts_[0].approach_direction.y();
      } else if (speed > 0) {
        const double scale = mu_[0] / speed;
        fax = scale * ux;
        fay = scale * uy;
      } else {
        fax = mu_[0] * contacts_[0].direction.x();
        fay = mu_[0] * contacts_[0].direction.y();
      }
      if (regularized(0)) {
        sigma_numerator *= speed;
        sigma_denominator *= speed + regularizing_slip_;
      }
    }
    if (slipping(1)) {
      const double ux = slip0_[1].x() - (coupling_x_ * ax + 3.5 * bx) * inverse_mass_;
      const double uy = slip0_[1].y() - (c_ * P + coupling_y_ * ay + 3.5 * by) * inverse_mass_;
      const double speed = std::sqrt(ux * ux + uy * uy);
      const double limit = mu_[1] * (s_ + c_ * fay);
      if (contacts_[1].approaching) {
        fbx = limit * contacts_[1].approach_direction.x();
        fby = limit * contacts_[1].approach_direction.y();
      } else if (speed > 0) {
        const double scale = limit / speed;
        fbx = scale * ux;
        fby = scale * uy;
      } else {
        fbx = limit * contacts_[1].direction.x();
        fby = limit * contacts_[1].direction.y();
      }
      if (regularized(1)) {
        sigma_numerator *= speed;
        sigma_denominator *= speed + regularizing_slip_;
      }
    }
    const double vy = vy0_ - (c_ * P - s_ * ay + by) * inverse_mass_;
    return scaledRate(sigma_numerator / sigma_denominator, fax, fay, fbx, fby, vy)
        .head<kStateSize>();
  }

  // Whether a slipping contact's slip turned by more than a right angle from `before` to `after`
  // (the slips at a step's start and end).
  bool slipReversed(const std::array<Eigen::Vector2d, 2>& before,
                    const std::array<Eigen::Vector2d, 2>& after) const {
    for (int k = 0; k < 2; ++k) {
      if (slipping(k) && !(before[k].dot(after[k]) > 0)) return true;
    }
    return false;
  }

  // One Dormand-Prince step. While both contacts slide, or one is held while the other slides, its
  // stages carry the slips (Extended) into that case's own rate, which GCC inlines into them.
  Step rungeKuttaStep(const State& z, const State& k1, double h) {
    if (bothSliding()) return extendedStep(z, k1, h, BothSlidingStage{this});
    if (clothHeldWhileNoseSlides()) return extendedStep(z, k1, h, ClothHeldStage{this});
    if (noseHeldWhileClothSlides()) return extendedStep(z, k1, h, NoseHeldStage{this});
    return finishStep(z, dp853Stages(z, k1, h, [this](const State& y) { return rate(y); }), h);
  }
  // The stages' rates of those three cases, inlined into them (as lambdas GCC stopped inlining them
  // once there were two).
  struct BothSlidingStage {
    ExactImpact* solver;
    [[gnu::always_inline]] Extended operator()(const Extended& y) const {
      return solver->bothSlidingRate(y, solver->normalVelocity(y));
    }
  };
  struct ClothHeldStage {
    ExactImpact* solver;
    [[gnu::always_inline]] Extended operator()(const Extended& y) const {
      return solver->clothHeldRate(y, solver->normalVelocity(y));
    }
  };
  struct NoseHeldStage {
    ExactImpact* solver;
    [[gnu::always_inline]] Extended operator()(const Extended& y) const {
      return solver->noseHeldRate(y, solver->normalVelocity(y));
    }
  };
  template <typename Rate>
  Step extendedStep(const State& z, const State& k1, double h, const Rate& rate) {
    return finishStep(z, dp853Stages(withSlips(z), withSlipRates(k1), h, rate), h);
  }

  // z + (h c_1 k_1 + ... + h c_n k_n), element by element, the coefficients given times h. The
  // newest rate comes last, so that only one product and two sums wait for it (the stages run one
  // after another, each on the one before).
  template <typename Vector>
  struct Term {
    double coefficient;
    const Vector* rate;
  };
  template <int n, typename Vector>
  static Vector stageInput(const Vector& z, const std::array<Term<Vector>, n>& terms) {
    Vector y;
    for (int i = 0; i < Vector::RowsAtCompileTime; ++i) {
      double sum = terms[0].coefficient * (*terms[0].rate)[i];
      for (int j = 1; j < n; ++j) sum += terms[j].coefficient * (*terms[j].rate)[i];
      y[i] = z[i] + sum;
    }
    return y;
  }

  // The twelve stages' rates of a step from z (k1 given), the step's end and the rate there.
  static constexpr int kStages = 12;
  template <typename Vector>
  struct Stages {
    std::array<Vector, kStages> k;
    Vector slope, end, rate_at_end;  // slope: the weighted rates, (end - z) / h
  };
  template <typename Vector, typename Rate>
  static Stages<Vector> dp853Stages(const Vector& z, const Vector& k1, double h, const Rate& rate) {
    using namespace dp853;
    using T = Term<Vector>;
    const Vector k2 = rate(stageInput<1, Vector>(z, {{T{h * a21, &k1}}}));
    const Vector k3 = rate(stageInput<2, Vector>(z, {{T{h * a31, &k1}, T{h * a32, &k2}}}));
    const Vector k4 = rate(stageInput<2, Vector>(z, {{T{h * a41, &k1}, T{h * a43, &k3}}}));
    const Vector k5 =
        rate(stageInput<3, Vector>(z, {{T{h * a51, &k1}, T{h * a53, &k3}, T{h * a54, &k4}}}));
    const Vector k6 =
        rate(stageInput<3, Vector>(z, {{T{h * a61, &k1}, T{h * a64, &k4}, T{h * a65, &k5}}}));
    const Vector k7 = rate(stageInput<4, Vector>(
        z, {{T{h * a71, &k1}, T{h * a74, &k4}, T{h * a75, &k5}, T{h * a76, &k6}}}));
    const Vector k8 = rate(stageInput<5, Vector>(
        z,
        {{T{h * a81, &k1}, T{h * a84, &k4}, T{h * a85, &k5}, T{h * a86, &k6}, T{h * a87, &k7}}}));
    const Vector k9 =
        rate(stageInput<6, Vector>(z, {{T{h * a91, &k1}, T{h * a94, &k4}, T{h * a95, &k5},
                                        T{h * a96, &k6}, T{h * a97, &k7}, T{h * a98, &k8}}}));
    const Vector k10 = rate(stageInput<7, Vector>(
        z, {{T{h * a101, &k1}, T{h * a104, &k4}, T{h * a105, &k5}, T{h * a106, &k6},
             T{h * a107, &k7}, T{h * a108, &k8}, T{h * a109, &k9}}}));
    const Vector k11 = rate(stageInput<8, Vector>(
        z, {{T{h * a111, &k1}, T{h * a114, &k4}, T{h * a115, &k5}, T{h * a116, &k6},
             T{h * a117, &k7}, T{h * a118, &k8}, T{h * a119, &k9}, T{h * a1110, &k10}}}));
    const Vector k12 = rate(stageInput<9, Vector>(
        z,
        {{T{h * a121, &k1}, T{h * a124, &k4}, T{h * a125, &k5}, T{h * a126, &k6}, T{h * a127, &k7},
          T{h * a128, &k8}, T{h * a129, &k9}, T{h * a1210, &k10}, T{h * a1211, &k11}}}));
    Stages<Vector> stages{{k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12}, {}, {}, {}};
    Vector& slope = stages.slope;
    for (int i = 0; i < Vector::RowsAtCompileTime; ++i) {
      slope[i] = b1 * k1[i] + b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] + b10 * k10[i] +
                 b11 * k11[i] + b12 * k12[i];
    }
    stages.end = z + h * slope;
    stages.rate_at_end = rate(stages.end);
    return stages;
  }

  // The step from z given its stages: its end, the rate there and its error.
  // (Of either vector type: only the state's part of each stage is read, none copied.)
  template <typename Vector>
  Step finishStep(const State& z, const Stages<Vector>& stages, double h) {
    using namespace dp853;
    const std::array<Vector, kStages>& k = stages.k;
    const Vector& k1 = k[0];
    const Vector &k6 = k[5], &k7 = k[6], &k8 = k[7], &k9 = k[8], &k10 = k[9], &k11 = k[10],
                 &k12 = k[11];
    Step step;
    step.z = stages.end.template head<kStateSize>();
    step.rate_at_end = stages.rate_at_end.template head<kStateSize>();
    State third, fifth;
    for (int i = 0; i < kStateSize; ++i) {
      third[i] = stages.slope[i] - bhh1 * k1[i] - bhh2 * k9[i] - bhh3 * k12[i];
      fifth[i] = er1 * k1[i] + er6 * k6[i] + er7 * k7[i] + er8 * k8[i] + er9 * k9[i] +
                 er10 * k10[i] + er11 * k11[i] + er12 * k12[i];
    }
    return finishStep(z, step, third, fifth, h);
  }
  // The step's error from the third- and fifth-order estimates' differences.
  Step finishStep(const State& z, Step step, State third, State fifth, double h) {
    using dp853::kThirdOrderWeight;
    // Combined estimate: |h| e5^2 / sqrt(n (e5^2 + w e3^2)), the norms scaled by the tolerances.
    // Only the error across the path counts: an error along it (of P and of the rest in the
    // proportions dz/dP at the step's end) is an error of the parameter tau, which the change of
    // variable makes large where sigma varies fast (a small slip) but which moves the step's end
    // along the path, not off it. So the estimates are taken at equal P. Not where a slip turned
    // by more than a right angle within the step (it passed by zero): there the end's direction
    // does not stand for the step, and the whole estimate counts.
    // (Two divisions and products with the scales' reciprocals: this runs between a step's last
    // rate and the next step's first stage, where each division's latency, and eighteen divisions'
    // turns at the divider, were waited for.)
    const std::array<Eigen::Vector2d, 2> slips_before = slips(z), slips_after = slips(step.z);
    step.slips_at_end = slips_after;
    if (!slipReversed(slips_before, slips_after) && step.rate_at_end[kP] > 0) {
      const double third_along = third[kP] / step.rate_at_end[kP];
      const double fifth_along = fifth[kP] / step.rate_at_end[kP];
      third -= third_along * step.rate_at_end;
      fifth -= fifth_along * step.rate_at_end;
      third[kP] = fifth[kP] = 0;
    }
    third = third.cwiseProduct(inverse_error_scale_);
    fifth = fifth.cwiseProduct(inverse_error_scale_);
    const double fifth_squared = fifth.squaredNorm(), third_squared = third.squaredNorm();
    double denominator = fifth_squared + kThirdOrderWeight * third_squared;
    if (!(denominator > 0)) denominator = 1;
    // Error per unit step: a step may add error in proportion to the share of the impact's impulse
    // it covers, so the errors of many steps add up to about the tolerance, not to their number
    // times it.
    const double share = std::max(std::abs(step.z[kP] - z[kP]) / impulse_scale_, kMinErrorShare);
    const double error_per_share =
        std::abs(h) * fifth_squared / (std::sqrt(State::RowsAtCompileTime * denominator) * share);
    step.error = std::max(error_per_share, smallSlipGrowthError(slips_before, slips_after));
    return step;
  }

  // The shortest step (tau) after a contact changes its law, at rate k1 (kRestartStepFraction); 0
  // where the rate does not advance P.
  double restartStep(const State& k1) const {
    return k1[kP] > 0 ? kRestartStepFraction * kFirstStepFraction * M_ * vy0_ / k1[kP] : 0.0;
  }

  // The longest step (tau) that spans kTurningScaleSteps of each slipping contact's turning scale
  // |u| / |du/dtau| at rate k1. An approaching slip falls along its line and is landed on instead;
  // a receding one grows away from the zero that sets its turning scale, which lies behind the
  // step (without that cap for it: 381.4 evaluations per impact of play instead of 384.9, the
  // largest error 3.5e-10 V0 instead of 3.3e-10; the spinning and grippy sets the same).
  double turningScaleStep(const std::array<Eigen::Vector2d, 2>& u, const State& k1) const {
    const std::array<Eigen::Vector2d, 2> change = slipChanges(k1);
    double step = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 2; ++k) {
      if (!slipping(k) || contacts_[k].approaching || contacts_[k].receding) continue;
      const double speed = change[k].norm();
      if (speed > 0) step = std::min(step, kTurningScaleSteps * u[k].norm() / speed);
    }
    return step;
  }

  // The longest step (tau) that spans kSlipDirectionTimeConstants of each slipping contact's slip
  // direction's time constant; infinite when no contact slips with friction along its slip. Across
  // its direction a slip u moves under its own friction at up to 7/2 mu / M per unit P (the largest
  // entry of the contacts' inverse effective mass, times M), which turns it at that over |u|;
  // dP/dtau = sigma turns the |u| of its own factor into |u| + s0 (a receding slip has none: its
  // |u| stays), and the other contact's factor |u'| / (|u'| + s0) in sigma slows it. The cloth's
  // friction is mu_s q with q at most s + c mu_w. (One division per contact: the step runs between
  // a step's last rate and the next step's first stage, where each division's latency is waited
  // for.)
  double slipDirectionStep(const std::array<Eigen::Vector2d, 2>& u) const {
    double step = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 2; ++k) {
      if (!slipping(k) || contacts_[k].approaching) continue;
      const int other = 1 - k;
      const double own = direction_time_scale_[k] * (u[k].norm() + factorSlip(k));
      if (!regularized(other)) {
        step = std::min(step, own);
        continue;
      }
      const double speed = u[other].norm();  // a zero other slip stops the turning: no bound
      if (speed > 0) step = std::min(step, own * (speed + regularizing_slip_) / speed);
    }
    return step;
  }

  // The step's change of a small growing slip against kSmallSlipGrowthPerStep, as an error of the
  // step's order (so that the step factor shortens the next try toward the allowed change, by at
  // most its clamp per try), from the slips at the step's start and end; 0 when no such slip
  // changes beyond it.
  double smallSlipGrowthError(const std::array<Eigen::Vector2d, 2>& before,
                              const std::array<Eigen::Vector2d, 2>& after) const {
    double error = 0;
    for (int k = 0; k < 2; ++k) {
      if (!slipping(k) || contacts_[k].approaching) continue;
      const double size = before[k].norm();
      if (!(size < regularizing_slip_) || !(after[k].norm() > size)) continue;
      const double ratio = (after[k] - before[k]).norm() / (kSmallSlipGrowthPerStep * size);
      if (ratio > 1) error = std::max(error, std::pow(ratio, kErrorOrder));
    }
    return error;
  }

  // Located events, each a function positive before it: the end of the phase (v_y in compression,
  // W - (1 - e^2) W_c in restitution), and for a held contact the instants its cone stops holding
  // it (it starts to slide along phi*) and holds it again (the margin of its needed friction).
  struct Event {
    bool phase_end = true;
    int contact = 0;         // for a held contact's events
    double sign = 1;         // +1: its cone stops holding it; -1: its cone holds it again
    bool creep_end = false;  // a held contact sliding along phi* has to slip as its own slip says
    bool approach_end = false;  // an approaching slip has reached its zero (has vanished)
    bool approach_off = false;  // an approaching slip has left its line: it slips as it says
  };
  double eventValue(const Event& event, const State& z) const {
    if (event.phase_end) return compressing_ ? normalVelocity(z) : z[kWork] - work_target_;
    if (event.creep_end) return creepRoom(event.contact, z);
    if (event.approach_end) {
      return contacts_[event.contact].approach_direction.dot(slip(event.contact, z)) -
             kApproachLanding * vanished_slip_;
    }
    if (event.approach_off) {
      return creep_error_limit_ -
             std::abs(cross(contacts_[event.contact].approach_direction, slip(event.contact, z)));
    }
    return event.sign * neededMargin(event.contact, z);
  }
  // How much more error the held law of contact k may make at z before its contact has to slip as
  // its own slip says (m/s; negative: past it): the limit less its slip's misalignment with phi*,
  // or less its slip scaled so that the limit is reached at the regularizing slip. Positive, and
  // at the limit, while its cone holds it (then the cone events apply).
  double creepRoom(int k, const State& z) const {
    const std::array<Eigen::Vector2d, 2> u = slips(z);
    const Laws laws = lawsAt(u, nullptr);
    if (laws.stick[k]) return creep_error_limit_;
    const double misalignment = std::abs(cross(u[k], laws.direction[k]));
    // (A slip from rest under the lag-corrected law is measured by its misalignment alone.)
    const double size =
        lagCorrected(k) ? 0 : u[k].norm() * (creep_error_limit_ / regularizing_slip_);
    return creep_error_limit_ - std::max(misalignment, size);
  }
  double eventSlope(const Event& event,
                    const State& r) const {  // d/dtau from the rate there; 0: none
    if (!event.phase_end) return 0;
    return compressing_ ? -(c_ * r[kP] - s_ * r[kAy] + r[kBy]) * inverse_mass_ : r[kWork];
  }
  double eventTolerance(const Event& event) const {
    // The held law may end anywhere its error is of the order of its limit: located loosely.
    if (event.creep_end) return kCreepEndLooseness * creep_error_limit_;
    if (event.approach_end) return kApproachLooseness * vanished_slip_;
    if (event.approach_off) return kCreepEndLooseness * creep_error_limit_;
    if (!event.phase_end) return kEventResidualFraction * options_.tolerance;
    return kEventResidualFraction * options_.tolerance * phaseEndScale();
  }
  // The phase ends are measured against the normal motion itself (v_y0, and the compression work),
  // not the whole velocity scale: in a grazing impact v_y0 can lie below tolerance times |v| + R
  // |w|, and compression would "end" at once with the ball still moving in.
  double phaseEndScale() const { return compressing_ ? vy0_ : result_.compression_work_J; }
  // How far inside its cone held contact k's stick friction would be at z (negative: outside),
  // the other contact following its own law given that k sticks: if it is held too, it slides along
  // its phi* when lawsAt would let it slide first (slidesFirst), and k's margin is taken against
  // that. So the sign says whether lawsAt holds k or lets it slide.
  double neededMargin(int k, const State& z) const {
    const std::array<Eigen::Vector2d, 2> u = slips(z);
    Laws laws;
    for (int j = 0; j < 2; ++j) {
      laws.stick[j] = held(j);
      laws.direction[j] =
          u[j].norm() > 0 ? Eigen::Vector2d(u[j].normalized()) : contacts_[j].direction;
    }
    const int other = 1 - k;
    if (held(other) && slidesFirst(laws, frictionFor(laws), u) == other)
      slideAlongCreep(other, &laws);
    return coneMargin(k, frictionFor(laws));
  }

  // Finds the step length in [0, h] that lands on an event the full step crossed: Newton on the
  // length where the event has a slope (each trial a full Runge-Kutta step, whose end rate gives
  // the next slope), Illinois regula falsi otherwise. Returns false, with *length set to a shorter
  // step to take instead, when a trial breaks the error tolerance.
  bool locate(const Event& event, const State& z, const State& k1, double h, const Step& full,
              double* length, Step* landed) {
    const double tolerance_g = eventTolerance(event);
    double lo = 0, g_lo = eventValue(event, z);
    double hi = h, g_hi = eventValue(event, full.z);
    *length = h;
    *landed = full;
    if (g_lo <= tolerance_g) {  // due where the step starts
      *length = 0;
      landed->z = z;
      landed->rate_at_end = k1;
      return true;
    }
    // Due where the step ends (a step cut to land on it, as an approaching slip's is): no trials.
    if (g_hi >= -tolerance_g && full.error <= 1) return true;
    auto newton = [](double from, double g, double slope) {
      return slope < 0 ? from - g / slope : -1.0;  // -1: outside any bracket, so not taken
    };
    // First guess: the root of the cubic through g and its slope at both ends of the full step (for
    // events with a slope), else Newton from the start.
    double trial = newton(0, g_lo, eventSlope(event, k1));
    const double slope_lo = eventSlope(event, k1), slope_hi = eventSlope(event, full.rate_at_end);
    if (event.phase_end && g_hi < 0)
      trial = h * hermiteRoot(g_lo, slope_lo * h, g_hi, slope_hi * h);
    int side = 0;
    for (int it = 0; it < kMaxEventIterations; ++it) {
      // A held law's error grows as the square of the impulse from where the slip was zero (the
      // lag of a direction that turns at a steady rate): the root of g = A - B t^2 through the
      // bracket's ends, which regula falsi would approach only slowly from the far end.
      if (event.creep_end && g_lo > g_hi) {
        if (lagCorrected(event.contact)) {  // corrected for the lag: about t^3
          const double lo3 = lo * lo * lo, hi3 = hi * hi * hi;
          trial = std::cbrt(lo3 + g_lo * (hi3 - lo3) / (g_lo - g_hi));
        } else {
          trial = std::sqrt(lo * lo + g_lo * (hi * hi - lo * lo) / (g_lo - g_hi));
        }
      }
      if (!(trial > lo && trial < hi) && g_lo > g_hi)
        trial = lo + (hi - lo) * (g_lo / (g_lo - g_hi));
      if (!(trial > lo && trial < hi)) trial = 0.5 * (lo + hi);
      const Step attempt = rungeKuttaStep(z, k1, trial);
      const double g = eventValue(event, attempt.z);
      // A trial that ends past the event may break the tolerance only because of what lies past
      // it (a held contact's law changes there, which the step does not resolve): it still bounds
      // the event from above, though it cannot be a landing. One that ends before it was too long.
      const bool accurate = attempt.error <= 1;
      if (!accurate && !(g <= tolerance_g && trial > lo)) {
        *length = trial * stepFactor(attempt.error);
        return false;
      }
      Step polished;
      double shift = 0;
      if (accurate && polishOnto(event, attempt, trial, &shift, &polished)) {
        *length = trial + shift;
        *landed = polished;
        return true;
      }
      if (g <= tolerance_g) {  // at or past the event
        hi = trial;
        g_hi = g;
        if (accurate) {  // a candidate landing
          *length = trial;
          *landed = attempt;
          if (g >= -tolerance_g) return true;
        }
        if (side == -1) g_lo *= 0.5;  // Illinois: keep one end from sticking
        side = -1;
      } else {
        lo = trial;
        g_lo = g;
        if (side == +1) g_hi *= 0.5;
        side = +1;
      }
      if (hi - lo <= kEventBracketUlps * kEpsilon * h) break;
      // (After an inaccurate trial its slope is no guide: the trial, now the bracket's end, makes
      // the next one regula falsi.)
      if (accurate) trial = newton(trial, g, eventSlope(event, attempt.rate_at_end));
    }
    // (A landing beyond the bracket is none: a trial that broke the tolerance past the event
    // moved the bracket's end below it.)
    if (landed->error <= 1 && *length <= hi) return true;
    // Only the full step, which broke the tolerance, saw the event: it may lie beyond. Take the
    // longest accurate stretch before it and look again from there.
    *length = lo > 0 ? lo : h * stepFactor(full.error);
    return false;
  }

  // A phase end missed by a little: the Newton correction of the step length is then so short
  // that a second-order step (Heun, one evaluation) from the trial's end covers it to the
  // tolerance, instead of another whole step from the start. Returns false (nothing spent but
  // that evaluation) when the correction is not that short or does not land on the event.
  bool polishOnto(const Event& event, const Step& from, double trial, double* shift,
                  Step* polished) {
    if (!event.phase_end) return false;
    const double g = eventValue(event, from.z), tolerance_g = eventTolerance(event);
    const double slope = eventSlope(event, from.rate_at_end);
    if (std::abs(g) <= tolerance_g || !(slope < 0)) return false;
    *shift = -g / slope;
    if (!(std::abs(*shift) <= kPolishStepFraction * trial)) return false;
    const State& start_rate = from.rate_at_end;
    const State end_rate = rate(from.z + *shift * start_rate);
    // Half the change of rate over the shift bounds Euler's error, and Heun's is far below it.
    const State change = (0.5 * *shift) * (end_rate - start_rate);
    if (!(change.cwiseQuotient(error_scale_).cwiseAbs().maxCoeff() <= kPolishErrorFraction))
      return false;
    polished->z = from.z + (0.5 * *shift) * (start_rate + end_rate);
    polished->rate_at_end = end_rate;  // for trace sampling only: the caller recomputes the rate
    polished->error = from.error;
    return std::abs(eventValue(event, polished->z)) <= tolerance_g;
  }

  // From the end of a step aimed at the phase end (past it or short of it by a little): third-order
  // steps (Bogacki-Shampine 3(2), the rate at the step's end reused as their first stage), each as
  // long as Newton's correction says, until the phase-end function is within its tolerance or its
  // rounding (kEventRoundingUlps). Returns false (with up to kMaxLandingSteps x 3 evaluations
  // spent) when they would reach more than kLandingShiftFraction of the step away, or their error
  // estimate exceeds kLandingErrorFraction of the tolerance: the step is then taken as it is.
  bool landOnPhaseEnd(const Step& aimed, double h, double* shift, Step* landed) {
    const Event phase;
    const double reachable =
        std::max(eventTolerance(phase), kEventRoundingUlps * kEpsilon * phaseEndScale());
    State y = aimed.z, k = aimed.rate_at_end;
    double moved = 0;
    for (int it = 0;; ++it) {
      const double g = eventValue(phase, y);
      if (std::abs(g) <= reachable) break;
      const double slope = eventSlope(phase, k);
      if (it == kMaxLandingSteps || !(slope < 0)) return false;
      const double s = -g / slope;
      if (!(std::abs(moved + s) <= kLandingShiftFraction * h)) return false;
      const State k2 = rate(y + (0.5 * s) * k);
      const State k3 = rate(y + (0.75 * s) * k2);
      const State next = y + s * ((2.0 / 9) * k + (1.0 / 3) * k2 + (4.0 / 9) * k3);
      const State k4 = rate(next);
      const State error = s * ((2.0 / 9 - 7.0 / 24) * k + (1.0 / 3 - 0.25) * k2 +
                               (4.0 / 9 - 1.0 / 3) * k3 - 0.125 * k4);
      if (!(error.cwiseQuotient(error_scale_).cwiseAbs().maxCoeff() <= kLandingErrorFraction))
        return false;
      y = next;
      k = k4;
      moved += s;
    }
    *shift = moved;
    landed->z = y;
    landed->rate_at_end = k;
    landed->error = aimed.error;
    return true;
  }

  // Whether an event other than the phase end (events[0]) is crossed at z: a landing that moved
  // forward past one is not taken, since that event would not be located.
  template <typename Events>
  bool crossedOther(const Events& events, const State& z) const {
    for (int i = 1; i < events.size(); ++i) {
      if (eventValue(events[i], z) <= 0) return true;
    }
    return false;
  }

  void setSlip(int k, const State& z, const Eigen::Vector2d& target) {
    slip0_[k] += target - slip(k, z);
  }

  void setMode(int k, ContactMode mode) {
    if (++changes_ > kMaxContactChanges)
      throw std::logic_error("cushion contacts changed state too often");
    contacts_[k].mode = mode;
    contacts_[k].creep_from_rest = false;
    // The cloth's slip from rest grew under the nose's sliding friction; once the nose is held it
    // grows otherwise, and the lag correction's origin no longer stands for it.
    if (mode == ContactMode::Stick) contacts_[1 - k].creep_from_rest = false;
    contacts_[k].approaching = false;
    contacts_[k].approach_blocked = false;
    contacts_[k].receding = false;
  }

  // Records the contacts' physical modes at z where they changed: a contact sticks while it is held
  // and its cone holds it, and slips otherwise (a held contact sliding along phi* slips). Between
  // located instants (the start, the phase ends) a change is recorded at the end of the step in
  // which it happened.
  void reportModes(const State& z) {
    Laws laws;  // needed only for a held contact (any other one slips)
    if (held(0) || held(1)) laws = lawsAt(slips(z), nullptr);
    for (int k = 0; k < 2; ++k) {
      if (contacts_[k].frictionless) continue;
      const ContactMode mode = held(k) && laws.stick[k] ? ContactMode::Stick : ContactMode::Slip;
      if (reported_[k] && *reported_[k] == mode) continue;
      reported_[k] = mode;
      result_.contact_changes.push_back({z[kP], k == 0 ? Contact::Cushion : Contact::Cloth, mode});
    }
  }

  // Holds contact k, whose slip has vanished: the leftover (below the vanishing threshold) is
  // removed, and the search for phi* gets a first guess over the whole circle. After an accepted
  // step: counts how long each slipping contact's slip has stayed small.
  void countSmallSlips(const std::array<Eigen::Vector2d, 2>& u) {
    for (int k = 0; k < 2; ++k) {
      const bool small = slipping(k) && u[k].norm() <= kStagnantSlipMultiple * vanished_slip_;
      contacts_[k].small_slip_steps = small ? contacts_[k].small_slip_steps + 1 : 0;
    }
  }

  // Held contact k slips as its own slip says from z on. Its slip is small, so its direction
  // turns over impulses of about |u| / |du/dP|: the next step is cut to that scale instead of
  // being found by rejections from the step the held law could take.
  void release(int k, const State& z) {
    const Eigen::Vector2d u = slip(k, z);
    contacts_[k].direction = u.normalized();
    setMode(k, ContactMode::Slip);
    contacts_[k].steady_rearm_slip = kSteadyRearmGrowth * u.norm();
    const double rate = slipRate(k, frictionFor(lawsAt(slips(z), nullptr))).norm();
    if (rate > 0)
      release_step_cap_ = std::min(release_step_cap_, kReleaseStepFraction * u.norm() / rate);
  }

  void hold(int k, const State& z) {
    contacts_[k].small_slip_steps = 0;
    contacts_[k].steady_rearm_slip = 0;
    const Eigen::Vector2d u = slip(k, z);
    if (u.norm() > 0) contacts_[k].direction = u.normalized();
    setSlip(k, z, Eigen::Vector2d::Zero());
    setMode(k, ContactMode::Stick);
    Laws laws = lawsAt(slips(z), nullptr);
    laws.stick[k] = true;
    contacts_[k].creep = creepDirectionSearch(k, laws);
    contacts_[k].creep_from_rest = true;
    contacts_[k].creep_origin = contacts_[k].creep;
    contacts_[k].creep_growth_order = 1;
  }

  // The step (in tau) after which held contact k, sliding along phi*, is predicted to have used
  // kCreepEndAim of its held law's room, so that its end falls due at the next step's start
  // instead of being crossed and located with a trial step. The misalignment grows as |u| times
  // phi*'s turn since the slip lay along it: m(t) = m0 + beta t (|u0| + g t / 2), with g the
  // slip's growth and beta phi*'s turn per unit tau (from phi* a little further along the path);
  // the size term grows as |u0| + g t. Infinite when nothing can be predicted.
  double heldLawStep(int k, const State& z, const State& k1) const {
    const double none = std::numeric_limits<double>::infinity();
    if (!(k1[kP] > 0)) return none;
    if (lagCorrected(k)) return none;  // its end is located (t^3, in locate)
    const std::array<Eigen::Vector2d, 2> u = slips(z);
    const Laws here = lawsAt(u, nullptr);
    if (here.stick[k]) return none;
    const double nudge = kCreepTurnProbe * impulse_scale_ / k1[kP];  // tau
    const Laws there = lawsAt(slips(z + nudge * k1), nullptr);
    if (there.stick[k]) return none;
    const double beta = std::abs(std::atan2(cross(here.direction[k], there.direction[k]),
                                            here.direction[k].dot(there.direction[k]))) /
                        nudge;
    const double growth = slipRate(k, frictionFor(here)).norm() * k1[kP];  // m/s per unit tau
    if (!(growth > 0)) return none;
    const double size = u[k].norm(), misalignment = std::abs(cross(u[k], here.direction[k]));
    const double aim = kCreepEndAim * creep_error_limit_;
    const double by_size = (aim / creep_error_limit_ * regularizing_slip_ - size) / growth;
    double by_turn = none;
    if (beta > 0) {  // root of (g beta / 2) t^2 + (|u0| beta) t + (m0 - aim) = 0
      const double a = 0.5 * growth * beta, b = size * beta, c = misalignment - aim;
      by_turn = c < 0 ? (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a) : 0;
    }
    const double t = std::min(by_size, by_turn);
    return t > 0 ? t : none;
  }

  // Whether slipping contact k slides steadily on the edge of its cone: its cone cannot hold it and
  // its small slip already lies along phi* (to within what the held law may miss). Such a slip
  // changes slowly while its direction is held stiffly in place; the held law describes it exactly
  // and is integrated in P.
  bool slidesSteadily(int k, const std::array<Eigen::Vector2d, 2>& u) {
    Laws laws = lawsAt(u, nullptr);
    laws.stick[k] = true;
    if (coneMargin(k, frictionFor(laws)) >= kConeSlackRelative) return false;
    Eigen::Vector2d phi;
    if (!creepDirection(k, laws, u[k].normalized(), &phi)) return false;
    // Along phi*, not against it: a slip passing through zero lies on phi*'s line too, but
    // sliding along phi* would reverse its friction before its slip has reached zero.
    if (!(u[k].dot(phi) > 0) || std::abs(cross(u[k], phi)) >= kSteadyCreepHold * creep_error_limit_)
      return false;
    contacts_[k].creep = phi;
    return true;
  }

  // du/dtau of both contacts under the rate dz/dtau.
  std::array<Eigen::Vector2d, 2> slipChanges(const State& r) const {
    const Eigen::Vector4d response = contactResponse(r[kAx], r[kAy], r[kBx], r[kBy]);
    return {Eigen::Vector2d(-response[0], -(response[1] - s_ * c_ * r[kP])) * inverse_mass_,
            Eigen::Vector2d(-response[2], -(response[3] + c_ * r[kP])) * inverse_mass_};
  }

  // The step (tau) that takes approaching contact k's slip to where its zero is located, at the
  // rate dz/dtau = k1: its slip falls linearly in P, so the step lands there (to rounding and the
  // slow change of the other contact) and the event is due at the next step's start instead of
  // being crossed, past which the slip's friction reverses. Infinite if it does not fall.
  double approachStep(int k, const State& z, const State& k1) const {
    const Eigen::Vector2d& line = contacts_[k].approach_direction;
    const double fall = -line.dot(slipChanges(k1)[k]);
    const double left = line.dot(slip(k, z)) - kApproachLanding * vanished_slip_;
    if (!(fall > 0) || !(left > 0)) return std::numeric_limits<double>::infinity();
    return left / fall;
  }

  // Which slipping contacts approach zero along their line (see kApproachEntry) and which recede
  // from it (kRecedingSlipMultiple), from the rate dz/dtau at z. When that changes, tau changes
  // meaning: the rate is taken again and the next step h rescaled to cover the same impulse.
  // Returns whether it changed.
  bool updateSlipsRunInP(const State& z, const std::array<Eigen::Vector2d, 2>& u, State* rate_here,
                         double* h) {
    const State& r = *rate_here;
    const std::array<Eigen::Vector2d, 2> change = slipChanges(r);  // du/dtau
    bool changed = false;
    for (int k = 0; k < 2; ++k) {
      ContactState& contact = contacts_[k];
      const double along = u[k].dot(change[k]), across = std::abs(cross(u[k], change[k]));
      // It runs along its line to its zero only if the turn its rate gives it on the way keeps its
      // slip within a share of the misalignment limit of that line (|u| across / -along is the
      // slip that turn builds up off the line by the time it reaches zero).
      const bool approaching = slipping(k) && !contact.approach_blocked && along < 0 &&
                               u[k].norm() * across <= -kApproachEntry * creep_error_limit_ * along;
      const bool receding = slipping(k) && !approaching && along > 0 &&
                            u[k].norm() >= kRecedingSlipMultiple * regularizing_slip_;
      if (receding != contact.receding) {
        contact.receding = receding;
        changed = true;
      }
      if (approaching == contact.approaching) continue;
      contact.approaching = approaching;
      if (approaching) contact.approach_direction = u[k].normalized();
      changed = true;
    }
    if (!changed) return false;
    const double before = r[kP];
    *rate_here = rate(z);
    if (before > 0 && (*rate_here)[kP] > 0) *h *= before / (*rate_here)[kP];
    previous_error_ = 0;
    return true;
  }

  // After an accepted step: held contacts remember where phi* was (the next step's first guess).
  void updateCreepGuesses(const State& z) {
    if (!held(0) && !held(1)) return;
    const Laws laws = lawsAt(slips(z), nullptr);
    for (int k = 0; k < 2; ++k) {
      if (held(k) && !laws.stick[k]) contacts_[k].creep = laws.direction[k];
    }
  }

  BallVelocity ballAt(const State& z) const {
    const BallVelocity change = impulseResponse(params_, z[kP], Eigen::Vector2d(z[kAx], z[kAy]),
                                                Eigen::Vector2d(z[kBx], z[kBy]));
    BallVelocity ball = incoming_;
    ball.v += change.v;
    ball.w += change.w;
    ball.v.z() = 0;  // held on the table by construction; removes rounding
    return ball;
  }

  void sample(const State& z) {
    ImpactSample s;
    s.impulse_Ns = z[kP];
    s.ball = ballAt(z);
    s.normal_work_J = z[kWork];
    s.cushion_slip = cushionSlip(params_, s.ball);
    s.cloth_slip = clothSlip(params_, s.ball);
    result_.trace.push_back(s);
  }

  // Trace samples inside an accepted step, at every multiple of the spacing in P: each is a
  // Runge-Kutta step of its own from the step's start, as accurate as the step (a cubic through the
  // step's ends finds its length). They do not change the integration.
  void sampleInside(const State& z0, const State& r0, double h, const State& z1, const State& r1) {
    const double spacing = options_.trace_spacing_Ns;
    auto P_at = [&](double t) {
      const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
      const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
      return h00 * z0[kP] + h10 * h * r0[kP] + h01 * z1[kP] + h11 * h * r1[kP];
    };
    const long evaluations = evaluations_;  // samples are not the solver's cost
    for (double next = (std::floor(z0[kP] / spacing) + 1) * spacing; next < z1[kP];
         next += spacing) {
      double lo = 0, hi = 1;
      for (int it = 0; it < 50; ++it) (P_at(0.5 * (lo + hi)) < next ? lo : hi) = 0.5 * (lo + hi);
      double length = 0.5 * (lo + hi) * h;
      Step sub = rungeKuttaStep(z0, r0, length);
      for (int it = 0; it < 3 && sub.rate_at_end[kP] > 0 && sub.z[kP] != next;
           ++it) {  // Newton on P
        length += (next - sub.z[kP]) / sub.rate_at_end[kP];
        sub = rungeKuttaStep(z0, r0, length);
      }
      sample(sub.z);
    }
    evaluations_ = evaluations;
  }

  const CushionParams params_;
  const BallVelocity incoming_;
  const ExactSolverOptions options_;
  double s_ = 0, c_ = 0, M_ = 0, inverse_mass_ = 0, vy0_ = 0, velocity_scale_ = 0;
  double impulse_scale_ = 0;  // N s, M V
  double vanished_slip_ = 0;  // m/s, kVanishedSlipFraction
  double regularizing_slip_ =
      0;  // m/s, s0 of the change of variable; also where held contacts slip
  double creep_error_limit_ = 0;  // m/s, kCreepErrorFraction
  // N s: the longest impulse the next step may cover after a release (infinite: no cap)
  double release_step_cap_ = std::numeric_limits<double>::infinity();
  // The last accepted ordinary step (tau) and its error, for predictive step control (error 0:
  // none since the last event or change).
  double previous_step_ = 0, previous_error_ = 0;
  // The phase-end function and its slope where the last accepted step started, and that step
  // (tau; 0: none comparable), to extrapolate the phase end from (valid while previous_error_ > 0
  // and last_step_ > 0); and the aimed
  // steps since the last event or change that did not land (kMaxMissedLandings).
  double last_phase_value_ = 0, last_phase_slope_ = 0, last_step_ = 0;
  int missed_landings_ = 0;
  std::array<double, 2> mu_;
  std::array<Eigen::Vector2d, 2> slip0_;  // slips at P = 0, shifted by setSlip
  // Entries of the contact matrix M G: [[7/2, 0, cx, 0], [0, s^2 + 5/2, 0, cy], [cx, 0, 7/2, 0],
  // [0, cy, 0, 7/2]] with cx = 1 - 5s/2, cy = 5/2 - s.
  double coupling_x_ = 0, coupling_y_ = 0, diagonal_y_ = 0;
  // The same entries divided by M, and s c / M and c / M, all in 1/kg (slipRatesOf).
  struct ScaledContactMatrix {
    double diagonal_x = 0, diagonal_y = 0, coupling_x = 0, coupling_y = 0, sin_cos = 0, cos = 0;
  } scaled_;
  // kSlipDirectionTimeConstants over 7/2 mu / M per contact (N s per unit of slip: the impulse over
  // which its own friction turns a slip of unit size by that many radians); infinite where that
  // rate is zero or too small for the quotient (see slipDirectionStep).
  std::array<double, 2> direction_time_scale_{};
  State error_scale_;
  State inverse_error_scale_;  // 1 / error_scale_, element by element
  std::array<ContactState, 2> contacts_;
  bool compressing_ = true;
  double work_target_ = 0;
  long evaluations_ = 0;
  int changes_ = 0;
  std::array<std::optional<ContactMode>, 2> reported_;  // the modes recorded last
  CushionImpactResult result_;
};

CushionImpactResult ExactImpact::run() {
  const bool tracing = options_.trace_spacing_Ns > 0;
  State z = State::Zero();
  for (int k = 0; k < 2; ++k) {
    if (contacts_[k].frictionless) continue;
    const Eigen::Vector2d u = slip(k, z);
    if (u.norm() <= vanished_slip_) {
      hold(k, z);
    } else {
      contacts_[k].direction = u.normalized();
      setMode(k, ContactMode::Slip);
    }
  }
  reportModes(z);
  if (tracing) sample(z);

  State k1 = rate(z);
  double h = kFirstStepFraction * M_ * vy0_;
  updateSlipsRunInP(z, slips(z), &k1, &h);  // a slip may already grow above 5 s0 (or fall)
  // The slips at z when an accepted step has just given them (not computed again at the top).
  std::optional<std::array<Eigen::Vector2d, 2>> slips_here;
  for (int steps = 0;; ++steps) {
    if (steps == kMaxSteps) throw std::logic_error("exact cushion solver exceeded its step budget");
    // Contact changes due here. A slip that has decayed below the threshold has vanished: the
    // contact is held. A held contact slips as its own slip says once that slip is large enough for
    // it (the regularizing slip), or as soon as its cone could hold it while it still slips (its
    // slip then shrinks, which the change of variable follows).
    bool changed = false;
    const std::array<Eigen::Vector2d, 2> u = slips_here ? *slips_here : slips(z);
    slips_here.reset();
    for (int k = 0; k < 2; ++k) {
      if (slipping(k) &&
          (u[k].norm() <= vanished_slip_ || contacts_[k].small_slip_steps > kStagnantSlipSteps)) {
        hold(k, z);
        changed = true;
      } else if (slipping(k) && u[k].norm() < kSteadyCreepFraction * regularizing_slip_ &&
                 u[k].norm() >= contacts_[k].steady_rearm_slip && slidesSteadily(k, u)) {
        setMode(k, ContactMode::Stick);  // its slip stays as it is: it already lies along phi*
        changed = true;
      } else if (held(k) && u[k].norm() > kReleaseSlipMultiple * vanished_slip_) {
        const Laws laws = lawsAt(u, nullptr);
        // While it slides along phi* the true slip lags phi* by an angle that grows with the slip,
        // and the friction along phi* misses that lag: the error shows as the slip's own
        // misalignment with phi*, which bounds how long the held law may run (creepRoom; its end
        // is located loosely, and is due here once within that looseness).
        if (laws.stick[k] || creepRoom(k, z) <= kCreepEndLooseness * creep_error_limit_) {
          release(k, z);
          changed = true;
        }
      }
    }
    if (changed) {
      previous_error_ = 0;
      missed_landings_ = 0;
      k1 = rate(z);
      h = std::max(h, restartStep(k1));
      updateSlipsRunInP(z, slips(z), &k1, &h);  // judged again under the new laws
      continue;
    }
    FixedList<Event, kMaxStepEvents> events;
    events.push_back(Event{});
    for (int k = 0; k < 2; ++k) {
      if (!held(k)) continue;
      // Armed only clear of the cone's edge, so that an event just applied cannot fire again at
      // once.
      const double margin = neededMargin(k, z);
      const Event candidate{false, k, margin < 0 ? -1.0 : 1.0};
      if (std::abs(margin) > eventTolerance(candidate)) events.push_back(candidate);
      // While it slides along phi* its held law runs only as long as it is accurate: the step
      // must not carry it past that (the error estimate cannot see it, the held law being smooth).
      // Also on the cone's edge (a break just located there), where the cone events are not armed.
      if (margin < eventTolerance(candidate)) {
        events.push_back(Event{false, k, 1.0, true});
        h = std::min(h, heldLawStep(k, z, k1));
      }
    }
    for (int k = 0; k < 2; ++k) {
      if (contacts_[k].approaching) {
        Event approach{false, k, 1.0, false};
        approach.approach_end = true;
        events.push_back(approach);
        Event off{false, k, 1.0, false};
        off.approach_off = true;
        events.push_back(off);
        h = std::min(h, approachStep(k, z, k1));
      }
    }
    if (std::isfinite(release_step_cap_)) {  // in tau, at the pace the rate sets here
      h = std::min(h, release_step_cap_ / k1[kP]);
      release_step_cap_ = std::numeric_limits<double>::infinity();
    }
    h = std::min(h, slipDirectionStep(u));
    h = std::min(h, turningScaleStep(u, k1));
    // Aim at a phase end predicted within the step (events[0]), extrapolated from the last
    // accepted step: landing from there costs a few cheap steps instead of trial steps.
    const double phase_value = eventValue(events[0], z), phase_slope = eventSlope(events[0], k1);
    const double proposed_h = h;
    double predicted = 0;
    const bool aimed = previous_error_ > 0 && missed_landings_ < kMaxMissedLandings &&
                       extrapolatedRoot(last_phase_value_, last_phase_slope_, phase_value,
                                        phase_slope, last_step_, h, &predicted);
    if (aimed) h = predicted;
    const Step step = rungeKuttaStep(z, k1, h);
    // Events are judged before the error, which may be large only because of what lies beyond them.
    // Every event the step crossed is located, and the step lands on the earliest: estimates from
    // the step's ends could order them wrongly (a cone margin is far from linear in the step).
    FixedList<int, kMaxStepEvents> crossed;
    for (int i = 0; i < events.size(); ++i) {
      if (eventValue(events[i], step.z) <= 0) crossed.push_back(i);
    }
    int first = -1;
    Step landed;
    double length = std::numeric_limits<double>::infinity();
    double shift = 0;
    const bool aim_landed =
        aimed && step.error <= 1 && (crossed.empty() || (crossed.size() == 1 && crossed[0] == 0)) &&
        landOnPhaseEnd(step, h, &shift, &landed) && !crossedOther(events, landed.z);
    if (aim_landed) {
      first = 0;
      length = h + shift;
    } else if (aimed && step.error <= 1) {
      ++missed_landings_;
    }
    if (!aim_landed && crossed.empty()) {
      if (step.error <= 1) {
        last_phase_value_ = phase_value;
        last_phase_slope_ = phase_slope;
        last_step_ = h;
        if (tracing) sampleInside(z, k1, h, step.z, step.rate_at_end);
        z = step.z;
        k1 = step.rate_at_end;
        updateCreepGuesses(z);
        const std::array<Eigen::Vector2d, 2>& u_end = step.slips_at_end;
        slips_here = u_end;
        countSmallSlips(u_end);
        // A slip that starts or stops approaching changes the scale of tau: the phase-end
        // function's slope there is no longer comparable with this one's.
        if (updateSlipsRunInP(z, u_end, &k1, &h)) last_step_ = 0;
        reportModes(z);
        if (tracing) sample(z);
        // Predictive control (Gustafsson): where the accepted steps' errors follow a trend (a slip
        // shrinking toward zero makes the right step shrink by a steady ratio) the next step
        // follows it too, instead of overshooting into a rejection every other step.
        double factor = stepFactor(step.error);
        if (previous_error_ > 0 && step.error > 0) {
          // (Two estimated roots: within 0.41 %, against the 10 % of the safety factor.)
          const double trend = (h / previous_step_) / inverseEighthRoot(previous_error_) *
                               inverseEighthRoot(step.error);
          factor = std::clamp(factor * trend, kStepMinFactor, kStepMaxFactor);
        }
        previous_step_ = h;
        previous_error_ = step.error;
        h *= factor;
      } else {
        h *= stepFactor(step.error);
      }
      continue;
    }
    // An event breaks the step trend, except a phase end landed on where nothing else happens (that
    // case is settled below, once the events due at the landing are known).
    if (!aim_landed) previous_error_ = 0;
    missed_landings_ = 0;
    bool retry = false;
    const double step_length = h;  // of `step`, which every event is located in
    for (int i : crossed) {
      if (aim_landed) break;  // on the phase end it was aimed at, the only event crossed
      Step candidate;
      double candidate_length = 0;
      if (!locate(events[i], z, k1, step_length, step, &candidate_length, &candidate)) {
        h = std::min(retry ? h : candidate_length, candidate_length);
        retry = true;
        continue;
      }
      if (candidate_length < length) {
        length = candidate_length;
        landed = candidate;
        first = i;
      }
    }
    if (retry) continue;  // a located stretch broke the tolerance: a shorter step first
    // The next step goes on as the controller proposed before any cut to aim (as after a located
    // event, which keeps the step that crossed it).
    if (aimed) h = proposed_h;
    if (tracing && length > 0) sampleInside(z, k1, length, landed.z, landed.rate_at_end);
    z = landed.z;
    updateCreepGuesses(z);
    bool phase_ends = false, contact_events = false;
    for (int i = 0; i < events.size(); ++i) {
      if (i != first && eventValue(events[i], z) > eventTolerance(events[i])) continue;
      if (events[i].phase_end) {
        phase_ends = true;
        continue;
      }
      contact_events = true;
      if (events[i].approach_end) {  // its slip has vanished (what is off its line is within
        hold(events[i].contact, z);  // the misalignment limit, which holding it removes)
        continue;
      }
      if (events[i].approach_off) {  // off its line: its friction follows its slip again
        contacts_[events[i].contact].approaching = false;
        contacts_[events[i].contact].approach_blocked = true;
        continue;
      }
      if (events[i].creep_end) {  // its held law has run its course: it slips as its slip says
        const int k = events[i].contact;
        const Eigen::Vector2d u = slip(k, z);
        if (held(k) && u.norm() > 0) release(k, z);
        continue;
      }
      if (events[i].sign > 0) {  // it slides along phi* from here (reportModes records it)
        const int k = events[i].contact;
        contacts_[k].creep_from_rest = false;
        contacts_[k].creep_origin = lawsAt(slips(z), nullptr).direction[k];
        contacts_[k].creep_from_rest = true;
        contacts_[k].creep_growth_order = 2;
        continue;
      }
      // The cone holds the contact again. With a slip left it slides (and its slip shrinks); with
      // none to speak of it sticks.
      const int k = events[i].contact;
      const Eigen::Vector2d u = slip(k, z);
      if (u.norm() > kReleaseSlipMultiple * vanished_slip_) {
        contacts_[k].direction = u.normalized();
        setMode(k, ContactMode::Slip);
      }
    }
    if (aim_landed && contact_events) {
      previous_error_ = 0;  // the laws changed at the landing: the trend is broken there too
    } else if (aim_landed) {
      // Only what ends the impact changed, not the dynamics: the trend of the steps before goes on.
      // The proposal was for a step from the aimed step's start (its length after the step's
      // bounds); where the steps shrink, their trend applies once more from the phase end (so the
      // first step after the end of compression is not rejected, as about half of them were, with
      // 1.3 rejections per impact of play within three steps of that end).
      h *= std::min(1.0, proposed_h / previous_step_);  // aimed: previous_step_ > 0
    }
    reportModes(z);
    if (tracing && length > 0) sample(z);
    k1 = rate(z);
    if (contact_events) h = std::max(h, restartStep(k1));
    updateSlipsRunInP(z, slips(z), &k1, &h);
    if (!phase_ends) continue;
    if (!compressing_) {
      result_.final_impulse_Ns = z[kP];
      result_.after = ballAt(z);
      break;
    }
    compressing_ = false;
    last_step_ = 0;  // the last step's phase-end values were of compression's function: none to
                     // extrapolate restitution's from
    result_.compression_impulse_Ns = z[kP];
    result_.compression_work_J = z[kWork];
    work_target_ = (1 - params_.restitution * params_.restitution) * z[kWork];  // eq. 17b
  }
  result_.rhs_evaluations = evaluations_;
  return std::move(result_);
}

}  // namespace

void validateExactSolverOptions(const ExactSolverOptions& options) {
  if (!(options.tolerance >= kMinTolerance && options.tolerance <= kMaxTolerance)) {
    rejectValue(
        "exact solver tolerance", options.tolerance,
        "it must lie in [" + valueText(kMinTolerance) + ", " + valueText(kMaxTolerance) + "]");
  }
  if (!(options.trace_spacing_Ns >= 0) || !std::isfinite(options.trace_spacing_Ns)) {
    rejectValue("trace spacing (N s)", options.trace_spacing_Ns, "it must be a finite number >= 0");
  }
}

CushionImpactResult solveCushionImpactExact(const CushionParams& params,
                                            const BallVelocity& incoming,
                                            const ExactSolverOptions& options) {
  validateCushionParams(params);
  validateIncomingBall(incoming);
  validateExactSolverOptions(options);
  return ExactImpact(params, incoming, options).run();
}

}  // namespace baize::physics
