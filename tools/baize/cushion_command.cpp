#include "tools/baize/cushion_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "physics/cushion_model.h"
#include "physics/cushion_paper_solver.h"
#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/progress.h"
#include "tools/baize/cushion_param_flags.h"
#include "tools/baize/cushion_run.h"
#include "tools/baize/cushion_sweep.h"

namespace baize::tools {
namespace {

struct CushionFlags {
  CushionShot shot;
  std::string solver = "exact";
  SolverSetting setting;
  CushionParamFlags cushion_flags;  // as given
  physics::CushionParams params;    // from cushion_flags, checked
  std::string json_path;  // the JSON object of the rebound, when set ("-": standard output)
  std::string sweep_directory;
  CLI::Option* sweep_flag = nullptr;
  CLI::Option* steps_flag = nullptr;      // the paper solver's only
  CLI::Option* tolerance_flag = nullptr;  // the exact solver's only
};

// The checks that belong to the flags themselves (the cushion parameters are cushionParamsOf's).
void validateFlags(const CushionFlags& flags) {
  const CushionShot& shot = flags.shot;
  requireFiniteFlag("--speed", shot.speed_mps);
  if (!(shot.speed_mps > 0)) rejectFlag("--speed", shot.speed_mps, "it must be > 0 (m/s)");
  requireFiniteFlag("--angle", shot.angle_deg);
  if (!(shot.angle_deg > 0 && shot.angle_deg < 180)) {
    rejectFlag("--angle", shot.angle_deg,
               "it must lie strictly between 0 and 180 degrees (90 is head-on)");
  }
  if (shot.speed_mps > physics::kMaxBallSpeed_mps) {
    rejectFlag("--speed", shot.speed_mps,
               "it must lie in (0, " + physics::valueText(physics::kMaxBallSpeed_mps) + "] m/s");
  }
  requireFiniteFlag("--topspin", shot.topspin_k);
  requireFiniteFlag("--sidespin", shot.sidespin_k);
  // A flag the chosen solver would ignore is refused: a user who sets it expects it to matter.
  if (flags.solver == "exact" && flags.steps_flag->count() > 0) {
    throw UsageError(
        "--steps sets the paper solver's increments; with --solver exact use --tolerance");
  }
  if (flags.solver == "paper" && flags.tolerance_flag->count() > 0) {
    throw UsageError(
        "--tolerance sets the exact solver's accuracy; with --solver paper use --steps");
  }
  if (flags.setting.paper_steps < 1 || flags.setting.paper_steps > physics::kMaxPaperSteps) {
    rejectFlag("--steps", flags.setting.paper_steps,
               "it must lie in [1, " + std::to_string(physics::kMaxPaperSteps) + "]");
  }
  requireFiniteFlag("--tolerance", flags.setting.exact_tolerance);
  if (!(flags.setting.exact_tolerance > 0)) {
    rejectFlag("--tolerance", flags.setting.exact_tolerance, "it must be > 0");
  }
}

std::string vectorText(const Eigen::Vector3d& x) {
  std::ostringstream out;
  out.precision(6);
  out << '(' << x.x() + 0.0 << ", " << x.y() + 0.0 << ", " << x.z() + 0.0 << ')';  // -0 prints as 0
  return out.str();
}

const char* contactName(physics::Contact contact) {
  return contact == physics::Contact::Cushion ? "cushion" : "cloth";
}

const char* modeName(physics::ContactMode mode) {
  return mode == physics::ContactMode::Stick ? "stick" : "slip";
}

void printHuman(const CushionFlags& flags, const physics::BallVelocity& incoming,
                const physics::CushionImpactResult& result) {
  const physics::CushionParams& p = flags.params;
  const CushionShot& shot = flags.shot;
  const Rebound rebound = reboundOf(result.after);
  std::ostream& out = std::cout;
  out << std::setprecision(6);
  out << "Ball-cushion impact, " << solverName(flags.setting.kind) << " solver ("
      << settingLabel(flags.setting) << ")\n";
  out << "  ball:      M = " << p.mass_kg << " kg, R = " << p.radius_m << " m\n";
  out << "  cushion:   h = " << p.contact_height_m
      << " m (sin theta = " << physics::contactSinTheta(p) << "), e_e = " << p.restitution;
  if (const auto& law = p.restitution_speed_dependence) {
    out << " up to " << law->knee_speed_mps << " m/s normal speed, times (" << law->knee_speed_mps
        << " / v)^" << law->falloff_exponent << " above";
  }
  out << ", mu_w = " << p.cushion_friction << "; cloth mu_s = " << p.cloth_friction << '\n';
  out << "  incoming:  V0 = " << shot.speed_mps << " m/s at alpha = " << shot.angle_deg
      << " deg, topspin " << shot.topspin_k << " V0/R, sidespin " << shot.sidespin_k << " V0/R\n";
  out << "             v = " << vectorText(incoming.v) << " m/s, w = " << vectorText(incoming.w)
      << " rad/s\n";
  out << "  outgoing:  v = " << vectorText(result.after.v)
      << " m/s, w = " << vectorText(result.after.w) << " rad/s\n";
  out << "  rebound:   speed " << rebound.speed_mps << " m/s at " << rebound.angle_deg
      << " deg from the cushion line; speed ratio " << rebound.speed_mps / shot.speed_mps << '\n';
  out << "  impulse:   P_c = " << result.compression_impulse_Ns
      << " N s (end of compression), P_f = " << result.final_impulse_Ns
      << " N s; W_c = " << result.compression_work_J << " J\n";
  out << "  contacts:";
  if (result.contact_changes.empty()) out << " (stick/slip changes not tracked by this solver)";
  for (const physics::ContactChange& change : result.contact_changes) {
    out << "\n    from P = " << change.impulse_Ns << " N s: " << contactName(change.contact) << ' '
        << (change.mode == physics::ContactMode::Stick ? "sticks" : "slips");
  }
  out << "\n  cost:      " << result.rhs_evaluations << " evaluations of dy/dP\n";
}

nlohmann::json vectorJson(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }

void writeJson(const CushionFlags& flags, const physics::BallVelocity& incoming,
               const physics::CushionImpactResult& result) {
  const physics::CushionParams& p = flags.params;
  const CushionShot& shot = flags.shot;
  const Rebound rebound = reboundOf(result.after);
  nlohmann::json changes = nlohmann::json::array();
  for (const physics::ContactChange& change : result.contact_changes) {
    changes.push_back({{"impulse_Ns", change.impulse_Ns},
                       {"contact", contactName(change.contact)},
                       {"mode", modeName(change.mode)}});
  }
  nlohmann::json out = {
      {"solver", solverName(flags.setting.kind)},
      {"setting", settingLabel(flags.setting)},
      {"params",
       {{"mass_kg", p.mass_kg},
        {"radius_m", p.radius_m},
        {"contact_height_m", p.contact_height_m},
        {"restitution", p.restitution},
        {"cushion_friction", p.cushion_friction},
        {"cloth_friction", p.cloth_friction}}},
      {"incoming",
       {{"speed_mps", shot.speed_mps},
        {"angle_deg", shot.angle_deg},
        {"topspin_k", shot.topspin_k},
        {"sidespin_k", shot.sidespin_k},
        {"v", vectorJson(incoming.v)},
        {"w", vectorJson(incoming.w)}}},
      {"v", vectorJson(result.after.v)},
      {"w", vectorJson(result.after.w)},
      {"speed", rebound.speed_mps},
      {"angle_deg", rebound.angle_deg},
      {"speed_ratio", rebound.speed_mps / shot.speed_mps},
      {"compression_impulse_Ns", result.compression_impulse_Ns},
      {"final_impulse_Ns", result.final_impulse_Ns},
      {"compression_work_J", result.compression_work_J},
      {"contact_changes", changes},
      {"rhs_evaluations", result.rhs_evaluations},
  };
  if (const auto& law = p.restitution_speed_dependence) {  // named as in a scene's physics.cushion
    out["params"]["restitution_speed_dependence"] = {{"knee_speed_mps", law->knee_speed_mps},
                                                     {"falloff_exponent", law->falloff_exponent}};
  }
  // nlohmann::json writes each double with the shortest digits that read back bit for bit.
  AtomicFile file(flags.json_path, "--json");
  file.stream() << out.dump(2) << '\n';
  file.commit();
}

// A physics refusal restated with the flag that set the value ("--tolerance = ...").
std::string namingTheSolverFlag(const std::string& physics_message) {
  static const std::pair<const char*, const char*> flag_of_quantity[] = {
      {"exact solver tolerance", "--tolerance"},
      {"paper solver steps", "--steps"},
  };
  for (const auto& [quantity, flag] : flag_of_quantity) {
    if (physics_message.rfind(quantity, 0) == 0) {
      return namingTheFlag(physics_message, quantity, flag);
    }
  }
  return namingTheCushionFlag(physics_message);
}

// The paper's scheme is first order: with too few increments it can hand back more energy than the
// ball brought, an outcome no impact has. Refused, as scenes refuse it (engine/models), naming the
// flag that set the increments.
void refuseEnergyGain(const CushionFlags& flags, const physics::BallVelocity& incoming,
                      const physics::BallVelocity& after) {
  if (flags.setting.kind != SolverKind::Paper) return;
  const double before_J = physics::kineticEnergy(flags.params, incoming);
  const double after_J = physics::kineticEnergy(flags.params, after);
  if (!(after_J > before_J * (1 + physics::kPaperEnergyGrowthAllowed))) return;
  throw UsageError("--steps " + std::to_string(flags.setting.paper_steps) +
                   ": the paper scheme made this impact gain energy (" +
                   physics::valueText(before_J) + " J in, " + physics::valueText(after_J) +
                   " J out), its first-order error: more increments (--steps) or the exact solver "
                   "(--solver exact) do not have it");
}

// The spins are given in units of V0/R, so their limit in those units depends on --speed and
// --radius: the refusal names all three, not the model's angular velocity components.
void refuseSpinBeyondModel(const CushionFlags& flags) {
  const double unit_radps = flags.shot.speed_mps / flags.params.radius_m;
  const double most_k = physics::kMaxBallSpin_radps / unit_radps;
  for (const auto& [flag, k] : {std::pair<const char*, double>{"--topspin", flags.shot.topspin_k},
                                {"--sidespin", flags.shot.sidespin_k}}) {
    if (std::abs(k) > most_k) {
      rejectFlag(flag, k,
                 "with --speed " + physics::valueText(flags.shot.speed_mps) + " and --radius " +
                     physics::valueText(flags.params.radius_m) + " its magnitude must be at most " +
                     physics::valueText(most_k) + " (a spin of " +
                     physics::valueText(physics::kMaxBallSpin_radps) + " rad/s)");
    }
  }
}

void solveAndPrint(CushionFlags& flags) {
  flags.setting.kind = flags.solver == "paper" ? SolverKind::Paper : SolverKind::Exact;
  validateFlags(flags);
  flags.params = cushionParamsOf(flags.cushion_flags);
  refuseSpinBeyondModel(flags);
  if (!flags.json_path.empty()) checkOutputPath("--json", flags.json_path);
  if (flags.sweep_flag->count() > 0) {
    for (const std::string& path :
         writeCushionSweep(flags.sweep_directory, flags.params, flags.setting)) {
      note(std::cout) << "wrote " << path << '\n';
    }
    return;
  }
  const physics::BallVelocity incoming = incomingBallOf(flags.shot, flags.params.radius_m);
  const physics::CushionImpactResult result =
      solveCushionShot(flags.params, incoming, flags.setting);
  refuseEnergyGain(flags, incoming, result.after);
  printHuman(flags, incoming, result);
  if (!flags.json_path.empty()) writeJson(flags, incoming, result);
}

void runCushion(CushionFlags& flags) {
  try {
    solveAndPrint(flags);
  } catch (const std::invalid_argument& rejected) {
    throw UsageError(namingTheSolverFlag(rejected.what()));
  }
}

}  // namespace

void addCushionCommand(CLI::App& parent) {
  auto flags = std::make_shared<CushionFlags>();
  CLI::App* command = parent.add_subcommand(
      "cushion",
      "Ball-cushion impact (Mathavan, Jackson & Parkin 2010): rebound of one shot, or with "
      "--sweep DIR the CSV data of the paper's figures 6, 7, 8 and 10");

  CLI::Option* speed =
      command->add_option("--speed", flags->shot.speed_mps, "incoming speed V0 (m/s)")
          ->capture_default_str();
  CLI::Option* angle =
      command
          ->add_option("--angle", flags->shot.angle_deg,
                       "incidence angle alpha from the cushion line (deg); 90 is head-on")
          ->capture_default_str();
  CLI::Option* topspin =
      command
          ->add_option("--topspin", flags->shot.topspin_k,
                       "topspin w_T in units of V0/R; 1 is natural roll, negative is backspin")
          ->capture_default_str();
  CLI::Option* sidespin =
      command
          ->add_option("--sidespin", flags->shot.sidespin_k,
                       "sidespin w_S in units of V0/R; positive is counter-clockwise from above")
          ->capture_default_str();
  command->add_option("--solver", flags->solver, "paper (Euler in P, section 3.4) or exact")
      ->check(CLI::IsMember({"paper", "exact"}))
      ->capture_default_str();
  flags->steps_flag =
      command->add_option("--steps", flags->setting.paper_steps, "paper solver: increments N")
          ->capture_default_str();
  flags->tolerance_flag = command
                              ->add_option("--tolerance", flags->setting.exact_tolerance,
                                           "exact solver: local error per step relative to V0")
                              ->capture_default_str();

  addCushionParamFlags(command, &flags->cushion_flags);
  addRestitutionSpeedFlags(command, &flags->cushion_flags);

  CLI::Option* json =
      command
          ->add_option("--json", flags->json_path,
                       "also write the rebound as one JSON object to this file (-: standard output)")
          ->check(notEmpty());
  flags->sweep_flag =
      command
          ->add_option("--sweep", flags->sweep_directory,
                       "write fig6.csv, fig7.csv, fig8.csv and fig10.csv into this directory "
                       "(created if missing) instead of solving one shot")
          ->excludes(speed)
          ->excludes(angle)
          ->excludes(topspin)
          ->excludes(sidespin)
          ->excludes(json)
          ->check(notEmpty());

  command->callback([flags] {
    if (const int status = runReportingErrors("cushion", [&] { runCushion(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
