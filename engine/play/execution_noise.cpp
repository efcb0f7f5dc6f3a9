#include "engine/play/execution_noise.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/value_text.h"

namespace baize::engine {
namespace {

constexpr double kDegToRad = M_PI / 180;
constexpr double kTwoPi = 2 * M_PI;
constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;  // 2^-53: one step of a 53-bit fraction

void requireSigma(const char* name, double value) {
  if (!std::isfinite(value) || value < 0) {
    throw std::invalid_argument(std::string("execution noise ") + name + " = " +
                                physics::valueText(value) +
                                " is not allowed: it must be finite and >= 0");
  }
}

// SplitMix64's finaliser: a bijection that spreads every input bit over the output.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

void validateExecutionNoise(const ExecutionNoise& noise) {
  requireSigma("tip offset sigma (m)", noise.tip_offset_sigma_m);
  requireSigma("elevation sigma (deg)", noise.elevation_sigma_deg);
  requireSigma("aim sigma (deg)", noise.aim_sigma_deg);
  requireSigma("speed sigma (m/s)", noise.speed_sigma_mps);
}

NormalGenerator::NormalGenerator(std::uint64_t seed) : bits_(seed) {}

double NormalGenerator::uniformOpenClosed() {
  return static_cast<double>((bits_() >> 11) + 1) * kTwoToMinus53;
}

double NormalGenerator::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // u1 in (0, 1] keeps the logarithm finite.
  const double radius = std::sqrt(-2 * std::log(uniformOpenClosed()));
  const double angle = kTwoPi * uniformOpenClosed();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

ExecutionError drawExecutionError(const ExecutionNoise& noise, double ball_radius_m,
                                  NormalGenerator* normal) {
  ExecutionError error;
  error.side_offset = noise.tip_offset_sigma_m / ball_radius_m * normal->next();
  error.height_offset = noise.tip_offset_sigma_m / ball_radius_m * normal->next();
  error.elevation_rad = noise.elevation_sigma_deg * kDegToRad * normal->next();
  error.heading_rad = noise.aim_sigma_deg * kDegToRad * normal->next();
  error.speed_mps = noise.speed_sigma_mps * normal->next();
  return error;
}

physics::CueShot perturbedShot(const physics::CueShot& intended, const ExecutionError& error) {
  physics::CueShot shot = intended;
  shot.side_offset += error.side_offset;
  shot.height_offset += error.height_offset;
  shot.elevation_rad = std::abs(shot.elevation_rad + error.elevation_rad);
  shot.heading_rad += error.heading_rad;
  shot.speed_mps = std::max(0.0, shot.speed_mps + error.speed_mps);
  return shot;
}

std::uint64_t sampleSeed(std::uint64_t seed, std::uint64_t case_index, std::uint64_t sample) {
  return mix(mix(mix(seed) ^ case_index) ^ sample);
}

}  // namespace baize::engine
