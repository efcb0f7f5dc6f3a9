#include "tools/baize/cushion_param_flags.h"

#include <optional>
#include <stdexcept>
#include <utility>

#include "tools/baize/cli_errors.h"

namespace baize::tools {
namespace {

// Each flag with the quantity physics names in its refusals and the parameter it sets.
struct CushionFlag {
  const char* flag;
  const char* quantity;
  double physics::CushionParams::*value;
};
constexpr CushionFlag kCushionFlags[] = {
    {"--mass", "ball mass (kg)", &physics::CushionParams::mass_kg},
    {"--radius", "ball radius (m)", &physics::CushionParams::radius_m},
    {"--h", "cushion contact height h (m)", &physics::CushionParams::contact_height_m},
    {"--e", "cushion restitution e_e", &physics::CushionParams::restitution},
    {"--mu-w", "cushion friction mu_w", &physics::CushionParams::cushion_friction},
    {"--mu-s", "cloth friction mu_s", &physics::CushionParams::cloth_friction},
};

// The speed law's flags with the keys physics names in its refusals.
constexpr std::pair<const char*, const char*> kSpeedLawFlags[] = {
    {"--knee-speed", "restitution_speed_dependence.knee_speed_mps"},
    {"--falloff-exponent", "restitution_speed_dependence.falloff_exponent"},
};

bool given(const CLI::Option* flag) { return flag != nullptr && flag->count() > 0; }

// The speed law when both its flags were given; nothing when neither was.
std::optional<physics::RestitutionSpeedDependence> speedLawOf(const CushionParamFlags& flags) {
  const bool knee = given(flags.knee_speed_flag), falloff = given(flags.falloff_exponent_flag);
  if (knee != falloff) {
    throw UsageError(std::string(knee ? "--knee-speed" : "--falloff-exponent") +
                     " was given without " + (knee ? "--falloff-exponent" : "--knee-speed") +
                     ": the speed dependence of e_e takes both");
  }
  if (!knee) return std::nullopt;
  requireFiniteFlag("--knee-speed", flags.speed_law.knee_speed_mps);
  requireFiniteFlag("--falloff-exponent", flags.speed_law.falloff_exponent);
  return flags.speed_law;
}

}  // namespace

void addRestitutionSpeedFlags(CLI::App* command, CushionParamFlags* flags) {
  flags->knee_speed_flag = command->add_option(
      "--knee-speed", flags->speed_law.knee_speed_mps,
      "knee speed of e_e's speed dependence (m/s): above this normal speed e_e falls as "
      "(knee / v)^p; with --falloff-exponent (default: no dependence)");
  flags->falloff_exponent_flag = command->add_option(
      "--falloff-exponent", flags->speed_law.falloff_exponent,
      "falloff exponent p of e_e's speed dependence, in [0, 1]; with --knee-speed");
}

void addCushionParamFlags(CLI::App* command, CushionParamFlags* flags) {
  physics::CushionParams& p = flags->params;
  command->add_option("--mass", p.mass_kg, "ball mass (kg)")->capture_default_str();
  command->add_option("--radius", p.radius_m, "ball radius (m)")->capture_default_str();
  flags->contact_height_flag = command->add_option(
      "--h", p.contact_height_m,
      "cushion contact height h above the slate (m); default 7R/5 of the radius in use");
  command->add_option("--e", p.restitution, "cushion restitution e_e (energetic)")
      ->capture_default_str();
  command->add_option("--mu-w", p.cushion_friction, "cushion friction mu_w")->capture_default_str();
  command->add_option("--mu-s", p.cloth_friction, "cloth friction mu_s")->capture_default_str();
}

physics::CushionParams cushionParamsOf(const CushionParamFlags& flags) {
  physics::CushionParams p = flags.params;
  if (flags.contact_height_flag == nullptr || flags.contact_height_flag->count() == 0) {
    p.contact_height_m = p.radius_m * 7.0 / 5.0;  // the paper's h = 7R/5
  }
  for (const CushionFlag& f : kCushionFlags) requireFiniteFlag(f.flag, p.*f.value);
  p.restitution_speed_dependence = speedLawOf(flags);
  try {
    physics::validateCushionParams(p);
  } catch (const std::invalid_argument& rejected) {
    throw UsageError(namingTheCushionFlag(rejected.what()));
  }
  return p;
}

std::string namingTheCushionFlag(const std::string& physics_message) {
  for (const CushionFlag& f : kCushionFlags) {
    if (physics_message.rfind(f.quantity, 0) == 0) {
      return namingTheFlag(physics_message, f.quantity, f.flag);
    }
  }
  for (const auto& [flag, key] : kSpeedLawFlags) {
    if (physics_message.rfind(key, 0) == 0) return namingTheFlag(physics_message, key, flag);
  }
  return physics_message;
}

}  // namespace baize::tools
