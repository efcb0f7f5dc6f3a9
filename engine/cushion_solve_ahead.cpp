#include "engine/cushion_solve_ahead.h"

#include <sched.h>

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <limits>
#include <mutex>
#include <thread>

#include "engine/cushion_contact.h"
#include "engine/shot_simulator.h"

namespace baize::engine {
namespace {

using Clock = std::chrono::steady_clock;

// How long the helper stays awake, watching for the next shot, after it last served one: shots
// run back to back (a bench, a planner's search) find it awake instead of paying the tens of
// microseconds a sleeping thread takes to wake.
constexpr auto kAwakeAfterShot = std::chrono::microseconds(500);
// How long the loop waits for an impact the helper is solving before solving it itself: far
// longer than a slow impact takes (about 0.1 ms), short against the milliseconds a helper
// descheduled on a busy machine may lose. After kSpinWait it yields its core while it waits, in
// case the helper is waiting for that core.
constexpr auto kLongestWait = std::chrono::microseconds(500);
constexpr auto kSpinWait = std::chrono::microseconds(20);

enum JobState : int { kEmpty, kQueued, kRunning, kDone, kFailed, kCancelled };

// One impact handed to the helper. The loop writes the input before it queues the job (release
// on `state`) and reads the output only once the helper has published it.
struct Job {
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

// The cores this process may run on (its affinity mask; the machine's count if unknown).
int usableCores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return CPU_COUNT(&set);
  return static_cast<int>(std::thread::hardware_concurrency());
}

std::atomic<bool> g_enabled{true};
std::atomic<long> g_taken_ahead{0};

}  // namespace

// The process's helper thread: it solves the claiming shot's queued impacts, earliest contact
// first, and otherwise waits for a shot (spinning a little, then asleep).
class CushionSolveAhead::Helper {
 public:
  static constexpr int kJobCount = 64;  // impacts in flight; with all taken the loop solves

  static Helper* claim(const SimulationParams& params) {
    static const bool two_cores = usableCores() >= 2;
    if (!two_cores || !g_enabled.load(std::memory_order_relaxed)) return nullptr;
    static Helper helper;
    return helper.tryClaim(params) ? &helper : nullptr;
  }

  // Stops serving the shot: its queued impacts are dropped; one being solved finishes (on the
  // helper's copy of the parameters) before the next shot can claim the helper.
  void release() {
    for (int j = 0; j < used_; ++j) {
      int queued = kQueued;
      jobs_[j].state.compare_exchange_strong(queued, kCancelled, std::memory_order_acq_rel);
    }
    serving_.store(false, std::memory_order_release);
    claimed_.store(false, std::memory_order_release);
  }

  // Solves the queued impact with the earliest contact, if there is one; whether it found one.
  // Called by the helper, and by the loop while it waits for the helper.
  bool solveOne() {
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
  Helper() : thread_([this] { run(); }) {}
  ~Helper() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  bool tryClaim(const SimulationParams& params) {
    bool free = false;
    if (!claimed_.compare_exchange_strong(free, true, std::memory_order_acquire)) return false;
    // An impact of the last shot may still be solving: it reads params_ and its job.
    for (int j = 0; j < used_; ++j)
      while (jobs_[j].state.load(std::memory_order_acquire) == kRunning) spinPause();
    params_ = params;
    for (int j = 0; j < used_; ++j) {
      jobs_[j].state.store(kEmpty, std::memory_order_relaxed);
      jobs_[j].ball = -1;
    }
    used_ = 0;
    used_shared_.store(0, std::memory_order_relaxed);
    {
      // Under the lock: a helper just going to sleep then either sees serving_ or is woken.
      std::lock_guard<std::mutex> lock(mutex_);
      serving_.store(true, std::memory_order_release);
    }
    wake_.notify_one();
    return true;
  }

  void run() {
    for (;;) {
      auto last_served = Clock::now();
      while (Clock::now() - last_served < kAwakeAfterShot) {
        if (!serving_.load(std::memory_order_acquire)) {
          spinPause();
          continue;
        }
        if (!solveOne()) spinPause();
        last_served = Clock::now();
      }
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return serving_.load(std::memory_order_acquire) || quit_; });
      if (quit_) return;
    }
  }

  std::atomic<bool> claimed_{false};  // a shot holds the helper
  std::atomic<bool> serving_{false};  // the shot may queue jobs
  int used_ = 0;                      // jobs [0, used_) were handed out in this shot (loop only)
  std::atomic<int> used_shared_{0};   // the same, for the helper
  SimulationParams params_;           // the claiming shot's
  std::array<Job, kJobCount> jobs_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool quit_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

void CushionSolveAhead::setEnabled(bool enabled) { g_enabled.store(enabled); }
bool CushionSolveAhead::enabled() { return g_enabled.load(); }
long CushionSolveAhead::impactsTakenAhead() { return g_taken_ahead.load(); }

CushionSolveAhead::CushionSolveAhead(const SimulationParams& params, int ball_count)
    : params_(params), job_of_ball_(ball_count, -1) {}

CushionSolveAhead::~CushionSolveAhead() {
  if (helper_) helper_->release();
}

void CushionSolveAhead::predict(int ball, double event_time_s,
                                const physics::BallVelocity& incoming) {
  if (!helper_) {
    if (claim_tried_) return;
    claim_tried_ = true;
    helper_ = Helper::claim(params_);
    if (!helper_) return;
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
        // Meanwhile solve a later impact the helper has not started, if there is one.
        if (!helper_->solveOne()) {
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
