// A thread the caller hands over for solving cushion impacts ahead (Box2D v3's and Jolt's pattern:
// the caller owns the threads). Nothing in Baize starts one on its own: a program that wants its
// shots' cushion impacts solved on a second core creates a worker and passes it to simulate(),
// ShotSimulation or runScene(). When a ball's earliest predicted event is a cushion or jaw contact
// while other balls move, its state at that instant is already known exactly, so the worker solves
// the impact while the event loop resolves the events before it (engine/sim/cushion_solve_ahead.h).
// Results are the same to the bit with or without a worker.
//
// One worker serves one shot at a time: a shot that finds it held by another thread's shot solves
// every impact itself. While it serves a shot, and for kAwakeAfterShot after the last one or after
// wake(), the worker spins on its core (waking a sleeping thread takes longer than an impact); then
// it sleeps until a shot asks for it. A shot that finds it asleep wakes it for the next shot and
// solves its own impacts itself, so a single shot never waits for a thread to wake.
#pragma once

#include <sched.h>

#include <array>
#include <atomic>
#include <cfenv>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "engine/sim/simulation_params.h"
#include "physics/cushion_model.h"

namespace baize::engine {

class CushionImpactWorker {
 public:
  // How long the worker stays awake after a shot, for the next one.
  static constexpr std::chrono::microseconds kAwakeAfterShot{2000};

  // Starts the thread, asleep. Throws std::system_error when no thread can be started.
  CushionImpactWorker();
  // Stops the thread and waits for it. No shot may hold the worker then.
  ~CushionImpactWorker();
  CushionImpactWorker(const CushionImpactWorker&) = delete;
  CushionImpactWorker& operator=(const CushionImpactWorker&) = delete;

  // Whether a worker is worth handing over on this machine: two or more cores in the calling
  // thread's affinity mask, and a cgroup CPU limit, if any, of two cores or more (under a smaller
  // one the worker's spinning spends the caller's CPU time). Read once.
  static bool secondCoreAvailable();

  // Wakes the worker and returns once it is awake (or after 0.1 s): shots in the next
  // kAwakeAfterShot find it awake.
  void wake();
  // Shots it served, and impacts whose answer the loop took from it (timing-dependent: for tests
  // and benchmarks, never part of a result).
  long shotsServed() const { return shots_served_.load(); }
  long impactsTakenAhead() const { return taken_ahead_.load(); }

 private:
  friend class CushionSolveAhead;
  static constexpr int kJobCount = 64;  // impacts in flight; with all taken the loop solves

  enum JobState : int { kEmpty, kQueued, kRunning, kDone, kFailed, kCancelled };
  // One impact handed over. The loop writes the input before it queues the job (release on
  // `state`) and reads the output only once the worker has published it. Each job on its own cache
  // line: the loop writes one while the worker polls the others.
  struct alignas(64) Job {
    std::atomic<int> state{kEmpty};
    std::atomic<double> event_time_s{0};  // read while queued, to take the earliest contact first
    int ball = -1;  // the ball whose prediction it holds (loop only); -1: free
    physics::BallVelocity input, output;
  };

  // For one shot (CushionSolveAhead): only if the worker is awake on another core, no other shot
  // holds it and no impact of the last shot is still being solved. A worker found asleep is woken.
  bool tryClaim(const SimulationParams& params);
  // Stops serving the shot: its queued impacts are dropped; one being solved finishes (on the
  // worker's copy of the parameters), and until then no shot can claim the worker.
  void release();
  // Solves the queued impact with the earliest contact, if there is one; whether it found one.
  // Called by the worker (in the shot's floating-point environment), and by the loop while it
  // waits for the worker.
  bool solveOne(bool set_environment);
  // A job free for a new prediction (loop only), or null when all are taken.
  Job* freeJob();
  Job& job(int j) { return jobs_[j]; }
  int indexOf(const Job* job) const { return static_cast<int>(job - jobs_.data()); }
  void countTakenAhead() { taken_ahead_.fetch_add(1, std::memory_order_relaxed); }

  void run();
  void moveOffCore(int core);
  void serveWhileAwake(bool can_move);
  void keepAwake();

  alignas(64) std::atomic<bool> claimed_{false};                // a shot holds the worker
  std::atomic<bool> serving_{false};                            // and may queue jobs
  std::atomic<bool> awake_{false};                              // spinning, not asleep
  std::atomic<bool> stopping_{false};                           // the destructor runs
  alignas(64) std::atomic<int> core_{-1};                       // where the worker last ran
  std::atomic<int> waker_core_{-1};                             // where the last wake-up came from
  std::atomic<std::chrono::steady_clock::rep> awake_until_{0};  // awake at least until then
  alignas(64) std::atomic<int> used_shared_{0};  // jobs [0, used) handed out in this shot
  int used_ = 0;                                 // the same, the loop's copy
  SimulationParams params_;                      // the claiming shot's
  std::fenv_t environment_;                      // and its floating-point environment
  std::array<Job, kJobCount> jobs_;
  std::atomic<long> shots_served_{0}, taken_ahead_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool wake_requested_ = false;  // under mutex_
  cpu_set_t own_cores_;          // the worker's affinity mask when it started (worker only)
  bool moved_ = false;           // moved off its waker's core (worker only)
  std::thread thread_;           // last: starts once the members above exist
};

}  // namespace baize::engine
