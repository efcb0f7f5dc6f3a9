// Event location of the exact cushion solver (the Mathavan 2010 model; method at the top of
// cushion_exact_solver.cpp): the ends of compression and restitution and a held contact's events
// (its cone stops or starts holding it, its held law runs out, an approaching slip vanishes or
// leaves its line), located on the length of the step that crossed them (Newton's method or
// Illinois regula falsi, each trial a full Runge-Kutta step; a cone event first at its root along
// the state's interpolant, then by secants), polished by a Heun step, or landed on from a step
// aimed at them by short third-order steps.
#pragma once

#include <new>
#include <stdexcept>
#include <type_traits>

#include "physics/cushion_step_control.h"

namespace baize::physics::cushion_exact {

// The end of a held law is located where its error lies within this fraction of the limit either
// side of it (where exactly does not matter; a loose bracket costs fewer trial steps).
constexpr double kCreepEndLooseness = 0.5;

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

// Located events, each a function positive before it: the end of the phase (v_y in compression,
// W - (1 - e^2) W_c in restitution), and for a held contact the instants its cone stops holding
// it (it starts to slide along phi*) and holds it again (the margin of its needed friction).
struct Event {
  bool phase_end = true;
  int contact = 0;            // for a held contact's events
  double sign = 1;            // +1: its cone stops holding it; -1: its cone holds it again
  bool creep_end = false;     // a held contact sliding along phi* has to slip as its own slip says
  bool approach_end = false;  // an approaching slip has reached its zero (has vanished)
  bool approach_off = false;  // an approaching slip has left its line: it slips as it says
  // Whether it is a held contact's cone event (the margin of its needed friction).
  bool cone() const { return !phase_end && !creep_end && !approach_end && !approach_off; }
};

class EventLocation : public StepControl {
 public:
  using StepControl::StepControl;

  // The event's function at z, positive before it.
  double eventValue(const Event& event, const State& z) const;
  // d/dtau of the event's function from the rate r there; 0: none.
  double eventSlope(const Event& event, const State& r) const;
  double eventTolerance(const Event& event) const;
  // The phase ends are measured against the normal motion itself (v_y0, and the compression work),
  // not the whole velocity scale: in a grazing impact v_y0 can lie below tolerance times |v| + R
  // |w|, and compression would "end" at once with the ball still moving in.
  double phaseEndScale() const { return compressing_ ? vy0_ : compression_work_; }
  // Locating a crossed event on the step that crossed it, and landing on an aimed phase end.
  bool locate(const Event& event, const State& z, const State& k1, double h, const Step& full,
              double* length, Step* landed);
  bool polishOnto(const Event& event, const Step& from, double trial, double* shift,
                  Step* polished);
  bool landOnPhaseEnd(const Step& aimed, double h, double* shift, Step* landed);

  // Whether an event other than the phase end (events[0]) is crossed at z: a landing that moved
  // forward past one is not taken, since that event would not be located.
  template <typename Events>
  bool crossedOther(const Events& events, const State& z) const {
    for (int i = 1; i < events.size(); ++i) {
      if (eventValue(events[i], z) <= 0) return true;
    }
    return false;
  }

 protected:
  bool compressing_ = true;
  double work_target_ = 0;
  double compression_work_ = 0;  // J, W_c once compression has ended
};

}  // namespace baize::physics::cushion_exact
