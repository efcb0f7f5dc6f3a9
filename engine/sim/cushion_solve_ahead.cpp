#include "engine/sim/cushion_solve_ahead.h"

#include <sched.h>

#include <array>
#include <atomic>
#include <cfenv>
#include <condition_variable>
#include <cstring>
#include <limits>
#include <mutex>
#include <thread>

#include "engine/sim/cpu_quota.h"
#include "engine/sim/cushion_contact.h"
#include "engine/sim/shot_simulator.h"

namespace baize::engine {
namespace {

using Clock = std::chrono::steady_clock;

// How long the loop waits for an impact the helper is solving before solving it itself: far
// longer than a slow impact takes (about 0.1 ms), short against the milliseconds a helper
// descheduled on a busy machine may lose. After kSpinWait it yields its core while it waits.
constexpr auto kLongestWait = std::chrono::microseconds(500);
constexpr auto kSpinWait = std::chrono::microseconds(20);
// How long wakeHelper() waits for the helper to be awake: a thread woken on a busy machine may
// wait for a core for milliseconds.
constexpr auto kLongestWakeWait = std::chrono::milliseconds(100);
// The helper notes the core it runs on every this many idle turns (a shot does not claim a helper
// on its own core).
constexpr int kCpuCheckTurns = 64;

enum JobState : int { kEmpty, kQueued, kRunning, kDone, kFailed, kCancelled };

// One impact handed to the helper. The loop writes the input before it queues the job (release
// on `state`) and reads the output only once the helper has published it. Each job on its own
// cache line: the loop writes one while the helper polls the others.
struct alignas(64) Job {
  std::atomic<int> state{kEmpty};
  std::atomic<double> event_time_s{0};  // read while queued, to take the earliest contact first
  int ball = -1;                        // the ball whose prediction it holds (loop only); -1: free
  physics::BallVelocity input, output;
};

bool sameBits(const physics::BallVelocity& a, const physics::BallVelocity& b) {
  return std::memcmp(a.v.data(), b.v.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.w.data(), b.w.data(), sizeof(double) * 3) == 0;
}

void spinPause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Whether this process may use two cores (twoCoresAllowed), read once: the cores in the affinity
// mask of the thread that first asks (the machine's count if unknown) and the cgroup CPU limit.
bool twoCores() {
  static const bool two = [] {
    cpu_set_t set;
    const int in_mask = sched_getaffinity(0, sizeof set, &set) == 0
                            ? CPU_COUNT(&set)
                            : static_cast<int>(std::thread::hardware_concurrency());
    return twoCoresAllowed(in_mask, cgroupCpuLimitCores());
  }();
  return two;
}

std::atomic<bool> g_enabled{true};
std::atomic<long> g_taken_ahead{0}, g_shots_served{0};
// When the last shot ended (steady clock ticks since its epoch).
constexpr Clock::rep kNoShotYet = std::numeric_limits<Clock::rep>::min();
std::atomic<Clock::rep> g_last_shot_end{kNoShotYet};

}  // namespace

// The process's helper thread. Asleep until a shot wakes it; then awake (spinning) until
// kAwakeAfterShot after the later of the last shot it served and the last wake-up, solving the
// claiming shot's queued impacts, earliest contact first, while one holds it. It is never
// destroyed: a shot may run while the program exits.
class CushionSolveAhead::Helper {
 public:
  static constexpr int kJobCount = 64;  // impacts in flight; with all taken the loop solves

  // The helper if it has been started, else null.
  static Helper* existing() { return instance_.load(std::memory_order_acquire); }
  // The helper, started if need be; null if its thread cannot start (then never again).
  static Helper* startOrGet() {
    if (Helper* helper = existing()) return helper;
    static std::mutex start_mutex;
    static bool start_failed = false;
    std::lock_guard<std::mutex> lock(start_mutex);
    if (Helper* helper = existing()) return helper;
    if (start_failed) return nullptr;
    try {
      Helper* helper = new Helper;
      instance_.store(helper, std::memory_order_release);
      return helper;
    } catch (...) {  // no thread (or no memory for it): shots run without the helper
      start_failed = true;
      return nullptr;
    }
  }
  // For this shot: only if the helper is awake on another core, no other shot holds it and no
  // impact of the last shot is still being solved (its job and the parameters are reused).
  bool tryClaim(const SimulationParams& params) {
    if (!awake_.load(std::memory_order_acquire)) return false;
    const int core = sched_getcpu();
    if (core >= 0 && core == core_.load(std::memory_order_relaxed)) return false;
    bool free = false;
    if (!claimed_.compare_exchange_strong(free, true, std::memory_order_acquire)) return false;
    for (int j = 0; j < used_; ++j) {
      if (jobs_[j].state.load(std::memory_order_acquire) == kRunning) {
        claimed_.store(false, std::memory_order_release);
        return false;
      }
    }
    params_ = params;
    std::fegetenv(&environment_);
    for (int j = 0; j < used_; ++j) {
      jobs_[j].state.store(kEmpty, std::memory_order_relaxed);
      jobs_[j].ball = -1;
    }
    used_ = 0;
    used_shared_.store(0, std::memory_order_relaxed);
    // Either this sees the helper about to sleep, or the helper sees it serving and stays awake
    // (both sequentially consistent).
    serving_.store(true, std::memory_order_seq_cst);
    if (!awake_.load(std::memory_order_seq_cst)) {
      release();
      return false;
    }
    g_shots_served.fetch_add(1, std::memory_order_relaxed);
    return true;
  }

  // Stops serving the shot: its queued impacts are dropped; one being solved finishes (on the
  // helper's copy of the parameters), and until then no shot can claim the helper.
  void release() {
    for (int j = 0; j < used_; ++j) {
      int queued = kQueued;
      jobs_[j].state.compare_exchange_strong(queued, kCancelled, std::memory_order_acq_rel);
    }
    serving_.store(false, std::memory_order_release);
    claimed_.store(false, std::memory_order_release);
  }

  bool awake() const { return awake_.load(std::memory_order_acquire); }

  // Keeps the helper awake for kAwakeAfterShot from now (waking it if it sleeps).
  void wake() {
    awake_until_.store((Clock::now() + kAwakeAfterShot).time_since_epoch().count(),
                       std::memory_order_relaxed);
    waker_core_.store(sched_getcpu(), std::memory_order_relaxed);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      wake_requested_ = true;
    }
    wake_.notify_one();
  }

  // Solves the queued impact with the earliest contact, if there is one; whether it found one.
  // Called by the helper (in the shot's floating-point environment), and by the loop while it
  // waits for the helper.
  bool solveOne(bool set_environment) {
    int best = -1;
    double best_time = std::numeric_limits<double>::infinity();
    const int used = used_shared_.load(std::memory_order_acquire);
    for (int j = 0; j < used; ++j) {
      if (jobs_[j].state.load(std::memory_order_relaxed) != kQueued) continue;
      const double t = jobs_[j].event_time_s.load(std::memory_order_relaxed);
      if (best < 0 || t < best_time) {
        best = j;
        best_time = t;
      }
    }
    if (best < 0) return false;
    Job& job = jobs_[best];
    int queued = kQueued;
    if (!job.state.compare_exchange_strong(queued, kRunning, std::memory_order_acq_rel))
      return true;  // taken meanwhile
    if (set_environment) std::fesetenv(&environment_);
    try {
      job.output = resolveCushionContact(params_, job.input);
      job.state.store(kDone, std::memory_order_release);
    } catch (...) {  // the loop solves it again and reports the error itself
      job.state.store(kFailed, std::memory_order_release);
    }
    return true;
  }

  // A job free for a new prediction (loop only), or null when all are taken.
  Job* freeJob() {
    for (int j = 0; j < kJobCount; ++j) {
      Job& job = jobs_[j];
      if (job.ball >= 0) continue;
      const int state = job.state.load(std::memory_order_acquire);
      if (state == kQueued || state == kRunning) continue;
      if (j >= used_) {
        used_ = j + 1;
        used_shared_.store(used_, std::memory_order_release);
      }
      return &job;
    }
    return nullptr;
  }
  Job& job(int j) { return jobs_[j]; }
  int indexOf(const Job* job) const { return static_cast<int>(job - jobs_.data()); }

 private:
  Helper() : thread_([this] { run(); }) { thread_.detach(); }

  void run() {
    const bool have_mask = sched_getaffinity(0, sizeof own_cores_, &own_cores_) == 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return wake_requested_; });
      wake_requested_ = false;
      lock.unlock();
      awake_.store(true, std::memory_order_seq_cst);
      serveWhileAwake(have_mask);
      // Free to run anywhere again while it sleeps.
      if (moved_) sched_setaffinity(0, sizeof own_cores_, &own_cores_);
      moved_ = false;
      lock.lock();
    }
  }

  // Moves the helper off `core` (where the thread that woke it runs, which needs that core) to
  // any other core of its mask: a woken thread is often placed beside its waker.
  void moveOffCore(int core) {
    cpu_set_t others = own_cores_;
    CPU_CLR(core, &others);
    if (CPU_COUNT(&others) == 0) return;
    if (sched_setaffinity(0, sizeof others, &others) == 0) moved_ = true;
  }

  // Serves shots until kAwakeAfterShot after the last one it served and after the last wake-up,
  // then returns with awake_ false. Where it finds itself on the core of the thread that woke it
  // (which needs that core) it moves to another (can_move: its affinity mask is known), or else
  // yields while idle.
  void serveWhileAwake(bool can_move) {
    Clock::rep served_until = 0;  // kAwakeAfterShot after the last shot served (clock ticks)
    for (long turn = 0;; ++turn) {
      int core = core_.load(std::memory_order_relaxed);
      if (turn % kCpuCheckTurns == 0) {
        core = sched_getcpu();
        if (can_move && !moved_ && core >= 0 &&
            core == waker_core_.load(std::memory_order_relaxed)) {
          moveOffCore(core);
          core = sched_getcpu();
        }
        core_.store(core, std::memory_order_relaxed);
      }
      if (serving_.load(std::memory_order_acquire)) {
        if (!solveOne(true)) spinPause();
        served_until = (Clock::now() + kAwakeAfterShot).time_since_epoch().count();
        continue;
      }
      const Clock::rep now = Clock::now().time_since_epoch().count();
      if (now < served_until || now < awake_until_.load(std::memory_order_relaxed)) {
        if (core >= 0 && core == waker_core_.load(std::memory_order_relaxed))
          std::this_thread::yield();
        else
          spinPause();
        continue;
      }
      awake_.store(false, std::memory_order_seq_cst);
      if (!serving_.load(std::memory_order_seq_cst)) return;  // to sleep until woken
      awake_.store(true, std::memory_order_seq_cst);          // a shot claimed it just now
    }
  }

  static std::atomic<Helper*> instance_;

  alignas(64) std::atomic<bool> claimed_{false};  // a shot holds the helper
  std::atomic<bool> serving_{false};              // and may queue jobs
  std::atomic<bool> awake_{false};                // spinning, not asleep
  alignas(64) std::atomic<int> core_{-1};         // where the helper last ran
  std::atomic<int> waker_core_{-1};               // where the last wake-up came from
  std::atomic<Clock::rep> awake_until_{0};        // awake at least until then (clock ticks)
  alignas(64) std::atomic<int> used_shared_{0};   // jobs [0, used) handed out in this shot
  int used_ = 0;                                  // the same, the loop's copy
  SimulationParams params_;                       // the claiming shot's
  std::fenv_t environment_;                       // and its floating-point environment
  std::array<Job, kJobCount> jobs_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool wake_requested_ = false;  // under mutex_
  cpu_set_t own_cores_;          // the helper's affinity mask when it started (helper only)
  bool moved_ = false;           // moved off its waker's core (helper only)
  std::thread thread_;           // last: starts once the members above exist
};

std::atomic<CushionSolveAhead::Helper*> CushionSolveAhead::Helper::instance_{nullptr};

void CushionSolveAhead::setEnabled(bool enabled) { g_enabled.store(enabled); }
bool CushionSolveAhead::enabled() { return g_enabled.load(); }
bool CushionSolveAhead::available() { return enabled() && twoCores() && Helper::startOrGet(); }
void CushionSolveAhead::wakeHelper() {
  if (!available()) return;
  Helper* helper = Helper::startOrGet();
  helper->wake();
  const auto asked = Clock::now();
  while (!helper->awake() && Clock::now() - asked < kLongestWakeWait) std::this_thread::yield();
}
long CushionSolveAhead::shotsServed() { return g_shots_served.load(); }
long CushionSolveAhead::impactsTakenAhead() { return g_taken_ahead.load(); }

CushionSolveAhead::CushionSolveAhead(const SimulationParams& params, int ball_count)
    : params_(params), started_(Clock::now()), job_of_ball_(ball_count, -1) {}

CushionSolveAhead::~CushionSolveAhead() {
  if (helper_) {
    helper_->release();  // awake for kAwakeAfterShot from its last job
  } else if (claim_tried_ && enabled() && twoCores()) {
    // A shot that could have used the helper, run back to back with the last one: keep (or get)
    // it awake for the next (it moves off this thread's core if it wakes there).
    const Clock::rep last = g_last_shot_end.load(std::memory_order_relaxed);
    const bool back_to_back =
        last != kNoShotYet &&
        started_.time_since_epoch().count() - last <
            std::chrono::duration_cast<Clock::duration>(kAwakeAfterShot).count();
    if (back_to_back) {
      if (Helper* helper = Helper::startOrGet()) helper->wake();
    }
  }
  g_last_shot_end.store(Clock::now().time_since_epoch().count(), std::memory_order_relaxed);
}

void CushionSolveAhead::predict(int ball, double event_time_s,
                                const physics::BallVelocity& incoming) {
  if (!helper_) {
    if (claim_tried_) return;
    claim_tried_ = true;
    if (!enabled() || !twoCores()) return;
    Helper* helper = Helper::existing();
    if (!helper || !helper->tryClaim(params_)) return;
    helper_ = helper;
  }
  // Predicted again unchanged (a neighbour's event made the loop look again): keep the job.
  if (job_of_ball_[ball] >= 0) {
    const Job& held = helper_->job(job_of_ball_[ball]);
    if (sameBits(held.input, incoming) && held.state.load(std::memory_order_acquire) != kCancelled)
      return;
  }
  forget(ball);
  Job* job = helper_->freeJob();
  if (!job) return;
  job->ball = ball;
  job->input = incoming;
  job->event_time_s.store(event_time_s, std::memory_order_relaxed);
  job->state.store(kQueued, std::memory_order_release);
  job_of_ball_[ball] = helper_->indexOf(job);
}

void CushionSolveAhead::forget(int ball) {
  if (!helper_) return;
  const int j = job_of_ball_[ball];
  if (j < 0) return;
  Job& job = helper_->job(j);
  int queued = kQueued;
  job.state.compare_exchange_strong(queued, kCancelled, std::memory_order_acq_rel);
  job.ball = -1;
  job_of_ball_[ball] = -1;
}

physics::BallVelocity CushionSolveAhead::resolve(int ball, const physics::BallVelocity& incoming) {
  if (helper_ && job_of_ball_[ball] >= 0) {
    Job& job = helper_->job(job_of_ball_[ball]);
    if (sameBits(job.input, incoming)) {
      int state = job.state.load(std::memory_order_acquire);
      if (state == kQueued) {  // not started: solved here (unless the helper takes it just now)
        job.state.compare_exchange_strong(state, kCancelled, std::memory_order_acq_rel);
      }
      const auto waiting_since = Clock::now();
      while (state == kRunning) {
        const auto waited = Clock::now() - waiting_since;
        if (waited > kLongestWait) break;
        // Meanwhile solve a later impact the helper has not started, if there is one (which can
        // overrun the wait by that impact).
        if (!helper_->solveOne(false)) {
          if (waited < kSpinWait)
            spinPause();
          else
            std::this_thread::yield();
        }
        state = job.state.load(std::memory_order_acquire);
      }
      if (state == kDone) {
        const physics::BallVelocity output = job.output;
        forget(ball);
        g_taken_ahead.fetch_add(1, std::memory_order_relaxed);
        return output;
      }
    }
    forget(ball);
  }
  return resolveCushionContact(params_, incoming);
}

}  // namespace baize::engine
