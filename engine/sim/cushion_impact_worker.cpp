#include "engine/sim/cushion_impact_worker.h"

#include <limits>

#include "engine/sim/cpu_quota.h"

namespace baize::engine {
namespace {

using Clock = std::chrono::steady_clock;

// How long wake() waits for the worker to be awake: a thread woken on a busy machine may wait for
// a core for milliseconds.
constexpr auto kLongestWakeWait = std::chrono::milliseconds(100);
// The worker notes the core it runs on every this many idle turns (a shot does not claim a worker
// on its own core).
constexpr int kCpuCheckTurns = 64;

void spinPause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

CushionImpactWorker::CushionImpactWorker() : thread_([this] { run(); }) {}

CushionImpactWorker::~CushionImpactWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_.store(true, std::memory_order_seq_cst);
    wake_requested_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

bool CushionImpactWorker::secondCoreAvailable() {
  static const bool two = [] {
    cpu_set_t set;
    const int in_mask = sched_getaffinity(0, sizeof set, &set) == 0
                            ? CPU_COUNT(&set)
                            : static_cast<int>(std::thread::hardware_concurrency());
    return twoCoresAllowed(in_mask, cgroupCpuLimitCores());
  }();
  return two;
}

void CushionImpactWorker::wake() {
  keepAwake();
  const auto asked = Clock::now();
  while (!awake_.load(std::memory_order_acquire) && Clock::now() - asked < kLongestWakeWait)
    std::this_thread::yield();
}

// Keeps the worker awake for kAwakeAfterShot from now (waking it if it sleeps).
void CushionImpactWorker::keepAwake() {
  awake_until_.store((Clock::now() + kAwakeAfterShot).time_since_epoch().count(),
                     std::memory_order_relaxed);
  waker_core_.store(sched_getcpu(), std::memory_order_relaxed);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_requested_ = true;
  }
  wake_.notify_one();
}

bool CushionImpactWorker::tryClaim(const SimulationParams& params) {
  if (!awake_.load(std::memory_order_acquire)) {
    keepAwake();  // for the next shot; this one does not wait for it
    return false;
  }
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
  // Either this sees the worker about to sleep, or the worker sees it serving and stays awake
  // (both sequentially consistent).
  serving_.store(true, std::memory_order_seq_cst);
  if (!awake_.load(std::memory_order_seq_cst)) {
    release();
    return false;
  }
  shots_served_.fetch_add(1, std::memory_order_relaxed);
  return true;
}

void CushionImpactWorker::release() {
  for (int j = 0; j < used_; ++j) {
    int queued = kQueued;
    jobs_[j].state.compare_exchange_strong(queued, kCancelled, std::memory_order_acq_rel);
  }
  serving_.store(false, std::memory_order_release);
  claimed_.store(false, std::memory_order_release);
}

bool CushionImpactWorker::solveOne(bool set_environment) {
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
    job.output = params_.cushion->resolve(params_, job.input);
    job.state.store(kDone, std::memory_order_release);
  } catch (...) {  // the loop solves it again and reports the error itself
    job.state.store(kFailed, std::memory_order_release);
  }
  return true;
}

CushionImpactWorker::Job* CushionImpactWorker::freeJob() {
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

void CushionImpactWorker::run() {
  const bool have_mask = sched_getaffinity(0, sizeof own_cores_, &own_cores_) == 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return wake_requested_; });
    wake_requested_ = false;
    if (stopping_.load(std::memory_order_seq_cst)) return;
    lock.unlock();
    awake_.store(true, std::memory_order_seq_cst);
    serveWhileAwake(have_mask);
    // Free to run anywhere again while it sleeps.
    if (moved_) sched_setaffinity(0, sizeof own_cores_, &own_cores_);
    moved_ = false;
    lock.lock();
  }
}

// Moves the worker off `core` (where the thread that woke it runs, which needs that core) to any
// other core of its mask: a woken thread is often placed beside its waker.
void CushionImpactWorker::moveOffCore(int core) {
  cpu_set_t others = own_cores_;
  CPU_CLR(core, &others);
  if (CPU_COUNT(&others) == 0) return;
  if (sched_setaffinity(0, sizeof others, &others) == 0) moved_ = true;
}

// Serves shots until kAwakeAfterShot after the last one it served and after the last wake-up, then
// returns with awake_ false. Where it finds itself on the core of the thread that woke it (which
// needs that core) it moves to another (can_move: its affinity mask is known), or else yields
// while idle.
void CushionImpactWorker::serveWhileAwake(bool can_move) {
  Clock::rep served_until = 0;  // kAwakeAfterShot after the last shot served (clock ticks)
  for (long turn = 0;; ++turn) {
    int core = core_.load(std::memory_order_relaxed);
    if (turn % kCpuCheckTurns == 0) {
      core = sched_getcpu();
      if (can_move && !moved_ && core >= 0 && core == waker_core_.load(std::memory_order_relaxed)) {
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
    if (!stopping_.load(std::memory_order_relaxed) &&
        (now < served_until || now < awake_until_.load(std::memory_order_relaxed))) {
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

}  // namespace baize::engine
