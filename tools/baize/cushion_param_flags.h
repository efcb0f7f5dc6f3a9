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
};

// Adds the six flags to `command`, writing into `flags`.
void addCushionParamFlags(CLI::App* command, CushionParamFlags* flags);

// The parameters the flags give (h = 7R/5 unless --h was given; flags never added count as not
// given), checked: a value that is not finite or out of its range is refused with a UsageError
// naming its flag.
physics::CushionParams cushionParamsOf(const CushionParamFlags& flags);

// A physics refusal of a cushion parameter ("ball mass (kg) = -1 is not allowed: ...") with the
// flag that set it named ("... (set by --mass)"); other messages unchanged.
std::string namingTheCushionFlag(const std::string& physics_message);

}  // namespace baize::tools
