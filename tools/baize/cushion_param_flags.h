// The cushion model's parameters as command-line flags (--mass, --radius, --h, --e, --mu-w,
// --mu-s), shared by `baize cushion` and `baize bench cushion`: defaults are the paper's snooker
// values, and h defaults to 7R/5 of the radius in use.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "physics/cushion_model.h"

namespace baize::tools {

struct CushionParamFlags {
  physics::CushionParams params;
  CLI::Option* contact_height_flag = nullptr;  // unset: h = 7R/5 of the radius in use
  physics::RestitutionSpeedDependence speed_law;  // used when both its flags are given
  CLI::Option* knee_speed_flag = nullptr;         // never added: the law stays off
  CLI::Option* falloff_exponent_flag = nullptr;
};

// Adds the six flags to `command`, writing into `flags`.
void addCushionParamFlags(CLI::App* command, CushionParamFlags* flags);

// Adds --knee-speed and --falloff-exponent, the optional speed dependence of e_e (as a scene's
// physics.cushion.restitution_speed_dependence), for commands that solve impacts exactly.
void addRestitutionSpeedFlags(CLI::App* command, CushionParamFlags* flags);

// The parameters the flags give (h = 7R/5 unless --h was given; the speed law when both its flags
// were given, one alone refused; flags never added count as not given), checked: a value that is not finite or out of its range is refused with a UsageError
// naming its flag.
physics::CushionParams cushionParamsOf(const CushionParamFlags& flags);

// A physics refusal of a cushion parameter ("ball mass (kg) = -1 is not allowed: ...") with the
// flag that set it named ("... (set by --mass)"); other messages unchanged.
std::string namingTheCushionFlag(const std::string& physics_message);

}  // namespace baize::tools
