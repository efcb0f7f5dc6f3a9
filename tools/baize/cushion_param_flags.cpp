#include "tools/baize/cushion_param_flags.h"

#include <stdexcept>
#include <utility>

#include "tools/baize/cli_errors.h"

namespace baize::tools {

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
  requireFiniteFlag("--mass", p.mass_kg);
  requireFiniteFlag("--radius", p.radius_m);
  requireFiniteFlag("--h", p.contact_height_m);
  requireFiniteFlag("--e", p.restitution);
  requireFiniteFlag("--mu-w", p.cushion_friction);
  requireFiniteFlag("--mu-s", p.cloth_friction);
  try {
    physics::validateCushionParams(p);
  } catch (const std::invalid_argument& rejected) {
    throw UsageError(namingTheCushionFlag(rejected.what()));
  }
  return p;
}

std::string namingTheCushionFlag(const std::string& physics_message) {
  static const std::pair<const char*, const char*> flag_of_quantity[] = {
      {"ball mass (kg)", "--mass"},
      {"ball radius (m)", "--radius"},
      {"cushion contact height h (m)", "--h"},
      {"cushion restitution e_e", "--e"},
      {"cushion friction mu_w", "--mu-w"},
      {"cloth friction mu_s", "--mu-s"},
  };
  for (const auto& [quantity, flag] : flag_of_quantity) {
    if (physics_message.rfind(quantity, 0) == 0) return physics_message + " (set by " + flag + ")";
  }
  return physics_message;
}

}  // namespace baize::tools
