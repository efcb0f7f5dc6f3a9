#include "engine/sim/cushion_solve_ahead.h"

#include <cstring>

#include "engine/sim/simulation_params.h"

namespace baize::engine {
namespace {

using Clock = std::chrono::steady_clock;

// How long the loop waits for an impact the worker is solving before solving it itself: far longer
// than a slow impact takes (about 0.1 ms), short against the milliseconds a worker descheduled on a
// busy machine may lose. After kSpinWait it yields its core while it waits.
constexpr auto kLongestWait = std::chrono::microseconds(500);
constexpr auto kSpinWait = std::chrono::microseconds(20);

bool sameBits(const physics::BallVelocity& a, const physics::BallVelocity& b) {
  return std::memcmp(a.v.data(), b.v.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.w.data(), b.w.data(), sizeof(double) * 3) == 0;
}

void spinPause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

CushionSolveAhead::CushionSolveAhead(const SimulationParams& params, int ball_count,
                                     CushionImpactWorker* worker)
    : params_(params), worker_(worker), job_of_ball_(worker ? ball_count : 0, -1) {}

CushionSolveAhead::~CushionSolveAhead() {
  if (held_) held_->release();  // it stays awake for kAwakeAfterShot from its last job
}

void CushionSolveAhead::predict(int ball, double event_time_s,
                                const physics::BallVelocity& incoming) {
  if (!held_) {
    if (claim_tried_ || !worker_) return;
    claim_tried_ = true;
    if (!worker_->tryClaim(params_)) return;
    held_ = worker_;
  }
  // Predicted again unchanged (a neighbour's event made the loop look again): keep the job.
  if (job_of_ball_[ball] >= 0) {
    const CushionImpactWorker::Job& kept = held_->job(job_of_ball_[ball]);
    if (sameBits(kept.input, incoming) &&
        kept.state.load(std::memory_order_acquire) != CushionImpactWorker::kCancelled)
      return;
  }
  forget(ball);
  CushionImpactWorker::Job* job = held_->freeJob();
  if (!job) return;
  job->ball = ball;
  job->input = incoming;
  job->event_time_s.store(event_time_s, std::memory_order_relaxed);
  job->state.store(CushionImpactWorker::kQueued, std::memory_order_release);
  job_of_ball_[ball] = held_->indexOf(job);
}

void CushionSolveAhead::forget(int ball) {
  if (!held_) return;
  const int j = job_of_ball_[ball];
  if (j < 0) return;
  CushionImpactWorker::Job& job = held_->job(j);
  int queued = CushionImpactWorker::kQueued;
  job.state.compare_exchange_strong(queued, CushionImpactWorker::kCancelled,
                                    std::memory_order_acq_rel);
  job.ball = -1;
  job_of_ball_[ball] = -1;
}

physics::BallVelocity CushionSolveAhead::resolve(int ball, const physics::BallVelocity& incoming) {
  if (held_ && job_of_ball_[ball] >= 0) {
    CushionImpactWorker::Job& job = held_->job(job_of_ball_[ball]);
    if (sameBits(job.input, incoming)) {
      int state = job.state.load(std::memory_order_acquire);
      if (state == CushionImpactWorker::kQueued) {  // not started: solved here (unless the
        // worker takes it just now)
        job.state.compare_exchange_strong(state, CushionImpactWorker::kCancelled,
                                          std::memory_order_acq_rel);
      }
      const auto waiting_since = Clock::now();
      while (state == CushionImpactWorker::kRunning) {
        const auto waited = Clock::now() - waiting_since;
        if (waited > kLongestWait) break;
        // Meanwhile solve a later impact the worker has not started, if there is one (which can
        // overrun the wait by that impact).
        if (!held_->solveOne(false)) {
          if (waited < kSpinWait)
            spinPause();
          else
            std::this_thread::yield();
        }
        state = job.state.load(std::memory_order_acquire);
      }
      if (state == CushionImpactWorker::kDone) {
        const physics::BallVelocity output = job.output;
        forget(ball);
        held_->countTakenAhead();
        return output;
      }
    }
    forget(ball);
  }
  return params_.cushion->resolve(params_, incoming);
}

}  // namespace baize::engine
