// Shared by the fuzz targets in tests/fuzz/: turning the fuzzer's bytes into numbers, and failing
// loudly. Each target defines LLVMFuzzerTestOneInput; it is linked either with libFuzzer (the
// BAIZE_FUZZ=ON build, clang) or with corpus_replay_main.cpp (every build: the CTest corpus
// replay).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>

namespace baize::fuzz {

// Prints what broke and aborts: libFuzzer saves the input as a crash, the replay test fails.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void check(bool condition, const std::string& what) {
  if (!condition) fail(what);
}

// Reads numbers from the fuzzer's bytes. Past the end every read gives 0 (so short inputs still
// make a complete call). Values come in three kinds, picked by a leading byte, so that the
// fuzzer reaches the physics (values of a plausible size) as well as the validation (anything):
// a raw 8-byte double (every bit pattern: NaN, infinities, subnormals, huge), one of a list of
// edge values, or a value of the caller's typical magnitude.
class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return position_ >= size_; }

  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }

  std::uint32_t word() {
    std::uint32_t w = 0;
    for (int i = 0; i < 4; ++i) w = (w << 8) | byte();
    return w;
  }

  double rawDouble() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = (bits << 8) | byte();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  // A uniform fraction in [0, 1] from 32 bits.
  double fraction() {
    return word() / static_cast<double>(std::numeric_limits<std::uint32_t>::max());
  }

  // A value around `scale` (either sign when `signed_range`), or now and then anything (see above).
  double value(double scale, bool signed_range = true) {
    const std::uint8_t kind = byte();
    if (kind < kRawKinds) return rawDouble();
    if (kind < kRawKinds + kEdgeKinds) return edgeValue(byte(), scale);
    const double u = fraction();
    return signed_range ? scale * (2 * u - 1) : scale * u;
  }

  // A value in [lo, hi] (never out of range: for parameters that must be valid to reach the
  // physics), or exactly lo or hi now and then.
  double inRange(double lo, double hi) {
    const std::uint8_t kind = byte();
    if (kind == 0) return lo;
    if (kind == 1) return hi;
    return lo + (hi - lo) * fraction();
  }

  // An integer in [lo, hi].
  int integer(int lo, int hi) {
    return lo + static_cast<int>(word() % static_cast<std::uint32_t>(hi - lo + 1));
  }

 private:
  // Of the 256 leading-byte values: 16 give a raw double, 32 an edge value, the rest a typical one.
  static constexpr std::uint8_t kRawKinds = 16;
  static constexpr std::uint8_t kEdgeKinds = 32;

  static double edgeValue(std::uint8_t which, double scale) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double values[] = {0.0,
                             -0.0,
                             std::numeric_limits<double>::quiet_NaN(),
                             kInf,
                             -kInf,
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::epsilon(),
                             1e-300,
                             1e300,
                             scale,
                             -scale,
                             scale * (1 + std::numeric_limits<double>::epsilon()),
                             scale * 1e-12,
                             scale * 1e12,
                             1.0,
                             -1.0};
    return values[which % (sizeof values / sizeof values[0])];
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

inline bool allFinite(std::initializer_list<double> values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

}  // namespace baize::fuzz
