// A guard that turns floating-point exceptions into crashes while physics code runs, for tests of
// the root finders, the cushion solvers, the ball-ball impact, the cloth motion and whole shots. A
// NaN or an infinity that a path produces quietly would otherwise flow on into results that may
// still pass a loose check; trapped, the first invalid operation, division by zero or overflow
// stops the test with SIGFPE at the instruction that did it (run the test under gdb to see where).
// Underflow and inexact results are normal in this code and are not trapped.
#pragma once

#include <fenv.h>

namespace baize::physics::test {

// While alive, an invalid operation, a division by zero or an overflow raises SIGFPE, so a path
// that would quietly produce NaN or infinity crashes the test instead. Restores the previous trap
// set and clears the flags on exit. Keep it around physics calls only (not around test macros).
class FloatingPointTraps {
 public:
  FloatingPointTraps() : previous_(fegetexcept()) {
    feclearexcept(FE_ALL_EXCEPT);
    feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
  }
  ~FloatingPointTraps() {
    fedisableexcept(FE_ALL_EXCEPT);
    feclearexcept(FE_ALL_EXCEPT);
    if (previous_ > 0) feenableexcept(previous_);
  }
  FloatingPointTraps(const FloatingPointTraps&) = delete;
  FloatingPointTraps& operator=(const FloatingPointTraps&) = delete;

 private:
  int previous_;
};

}  // namespace baize::physics::test
