#include "tools/baize/calibrate_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/fit/cushion_calibration.h"
#include "engine/io/ball_set.h"
#include "engine/io/table.h"
#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/calibrate_report.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"
#include "tools/baize/progress.h"
#include "tools/baize/thread_flag.h"

namespace baize::tools {
namespace {

struct CalibrateFlags {
  std::string data;
  std::string table = "pool-9ft";
  std::string ball_set;  // empty: the set of the table's kind
  std::string fit = "restitution,friction";
  double max_speed_mps = engine::kDefaultCalibrationMaxSpeed_mps;
  CLI::Option* max_speed_flag = nullptr;
  double e = 0, mu_w = 0, h = 0, mu_s = 0;  // --e, --mu-w, --h, --mu-s: start or fixed values
  CLI::Option *e_flag = nullptr, *mu_w_flag = nullptr, *h_flag = nullptr, *mu_s_flag = nullptr;
  // --knee-speed, --falloff-exponent: the speed dependence's start or fixed values
  physics::RestitutionSpeedDependence law = engine::kSpeedDependenceFitStart;
  CLI::Option *knee_flag = nullptr, *falloff_flag = nullptr;
  int threads = 0;
  std::string png_path;
  std::string json_path;
  const Drawing* drawing = nullptr;  // draws --png; none in a build without rendering
};

// A shipped name, else a file.
engine::Table tableOf(const std::string& text) {
  const std::vector<std::string> names = engine::builtinTableNames();
  if (std::find(names.begin(), names.end(), text) != names.end()) return engine::builtinTable(text);
  return engine::loadTable(text);
}

engine::BallSet ballSetOf(const std::string& text) {
  const std::vector<std::string> names = engine::builtinBallSetNames();
  if (std::find(names.begin(), names.end(), text) != names.end())
    return engine::builtinBallSet(text);
  return engine::loadBallSet(text);
}

std::vector<engine::CushionFitParameter> fittedOf(const std::string& list) {
  std::vector<engine::CushionFitParameter> fitted;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    const auto parameter = engine::fitParameterNamed(name);
    if (!parameter) {
      std::string names;
      for (const std::string& known : engine::fitParameterNames())
        names += (names.empty() ? "" : ", ") + known;
      throw UsageError("--fit '" + list + "' is not allowed: '" + name +
                       "' is not a parameter; the list takes " + names +
                       ", separated by commas");
    }
    if (std::find(fitted.begin(), fitted.end(), *parameter) != fitted.end()) {
      throw UsageError("--fit '" + list + "' is not allowed: " + name + " is named twice");
    }
    fitted.push_back(*parameter);
  }
  if (fitted.empty()) throw UsageError("--fit '' is not allowed: name at least one parameter");
  return fitted;
}

// The table's and ball set's values with the flags given in their place, checked by the model.
physics::CushionParams startOf(const CalibrateFlags& flags) {
  const engine::Table table = tableOf(flags.table);
  const engine::BallSet balls = ballSetOf(
      !flags.ball_set.empty() ? flags.ball_set
                              : (table.kind == engine::TableKind::Snooker ? "snooker" : "pool"));
  physics::CushionParams p = engine::calibrationStart(table, balls);
  if (flags.e_flag->count()) p.restitution = flags.e;
  if (flags.mu_w_flag->count()) p.cushion_friction = flags.mu_w;
  if (flags.h_flag->count()) p.contact_height_m = flags.h;
  if (flags.mu_s_flag->count()) p.cloth_friction = flags.mu_s;
  if (flags.knee_flag->count() || flags.falloff_flag->count()) p.restitution_speed_dependence = flags.law;
  try {
    physics::validateCushionParams(p);
  } catch (const std::invalid_argument& refused) {
    throw UsageError(std::string("the starting values are refused: ") + refused.what() +
                     " (they come from --table " + flags.table + ", its ball set and --e, "
                     "--mu-w, --h, --mu-s, --knee-speed, --falloff-exponent where given)");
  }
  return p;
}

void checkFlags(const CalibrateFlags& flags) {
  requireFiniteFlag("--max-speed", flags.max_speed_mps);
  if (!(flags.max_speed_mps > 0)) rejectFlag("--max-speed", flags.max_speed_mps, "it must be > 0 (m/s)");
  if (!flags.png_path.empty()) checkOutputPath("--png", flags.png_path);
  if (!flags.json_path.empty()) checkOutputPath("--json", flags.json_path);
}

// The speed dependence is fitted to the fast points the rigid model leaves out: without
// --max-speed, none are left out then.
double maxSpeedOf(const CalibrateFlags& flags,
                  const std::vector<engine::CushionFitParameter>& fitted) {
  if (flags.max_speed_flag->count()) return flags.max_speed_mps;
  const bool law = std::any_of(fitted.begin(), fitted.end(), engine::isSpeedDependenceParameter);
  return law ? std::numeric_limits<double>::infinity() : flags.max_speed_mps;
}

void writeOutputs(const CalibrateFlags& flags, const engine::CushionCalibration& fit) {
  if (!flags.png_path.empty()) {
    flags.drawing->writeCalibrationChart(fit, flags.png_path);
    note(std::cout) << "wrote " << flags.png_path << '\n';
  }
  if (!flags.json_path.empty()) {
    AtomicFile file(flags.json_path, "--json");
    file.stream() << calibrationJson(fit).dump(2) << '\n';
    file.commit();
    if (flags.json_path != "-") note(std::cout) << "wrote " << flags.json_path << '\n';
  }
}

void runCalibrate(const CalibrateFlags& flags) {
  checkFlags(flags);
  engine::CushionCalibrationSetup setup;
  setup.fitted = fittedOf(flags.fit);
  setup.start = startOf(flags);
  setup.max_speed_mps = maxSpeedOf(flags, setup.fitted);
  setup.threads = threadsOfFlag(flags.threads);
  const std::vector<engine::CushionMeasurement> data = engine::readCushionMeasurements(flags.data);
  engine::CushionCalibration fit;
  try {
    fit = engine::calibrateCushion(data, setup);
  } catch (const std::invalid_argument& refused) {
    throw UsageError(flags.data + ": " + refused.what() + " (--max-speed " +
                     physics::valueText(setup.max_speed_mps) + ", --fit " + flags.fit + ")");
  }
  // With the JSON on standard output this goes to standard error (tools/baize/standard_output.h).
  printCalibration(fit, std::cout);  // the result: --quiet drops only notes and progress
  writeOutputs(flags, fit);
}

void addStartFlags(CLI::App* command, CalibrateFlags* flags) {
  flags->e_flag = command->add_option("--e", flags->e, "restitution e_e: start, or fixed if not fitted (default: the table's)");
  flags->mu_w_flag = command->add_option("--mu-w", flags->mu_w, "cushion friction mu_w: start or fixed (default: the table's)");
  flags->h_flag = command->add_option("--h", flags->h, "nose height above the slate, m: start or fixed (default: the table's)");
  flags->mu_s_flag = command->add_option("--mu-s", flags->mu_s, "cloth friction mu_s: start or fixed (default: the table kind's cloth)");
  flags->knee_flag = command->add_option("--knee-speed", flags->law.knee_speed_mps, "knee speed of the restitution's speed dependence, m/s: start or fixed (default 2.5; given, the dependence is on)");
  flags->falloff_flag = command->add_option("--falloff-exponent", flags->law.falloff_exponent, "falloff exponent of the restitution's speed dependence: start or fixed (default 0.5; given, the dependence is on)");
}

}  // namespace

void addCalibrateCommand(CLI::App& parent, const Drawing* drawing) {
  auto flags = std::make_shared<CalibrateFlags>();
  flags->drawing = drawing;
  CLI::App* command = parent.add_subcommand(
      "calibrate",
      "Fit the cushion model (restitution, friction; on request nose height and cloth friction) "
      "to measured rebounds in a CSV file (docs/calibrate.md)");
  command->add_option("data", flags->data,
                      "CSV: speed_mps,angle_deg,topspin,sidespin,rebound_speed_mps,"
                      "rebound_angle_deg (topspin, sidespin, rebound_angle_deg optional)")
      ->required()
      ->check(notEmpty());
  command->add_option("--table", flags->table, "a shipped table's name or a table file")
      ->capture_default_str()
      ->check(notEmpty());
  command->add_option("--ball-set", flags->ball_set,
                      "a shipped ball set's name or a ball-set file (default: pool, or snooker on a "
                      "snooker table)")
      ->check(notEmpty());
  command->add_option("--fit", flags->fit,
                      "the parameters fitted, separated by commas: restitution, friction, "
                      "contact_height_m, sliding_friction, knee_speed_mps, falloff_exponent")
      ->capture_default_str();
  flags->max_speed_flag =
      command
          ->add_option("--max-speed", flags->max_speed_mps,
                       "points with a faster incoming speed (m/s) are left out and counted (default "
                       "none when knee_speed_mps or falloff_exponent is fitted)")
          ->capture_default_str();
  addStartFlags(command, flags.get());
  command->add_option("--threads", flags->threads, kThreadsHelp)->capture_default_str();
  needsDrawing(*command,
               command
                   ->add_option("--png", flags->png_path,
                                "write a chart of measured and fitted rebound speeds"),
               drawing)
      ->check(notEmpty());
  command->add_option("--json", flags->json_path,
                      "write the fit as JSON to this file ('-': standard output; the text report then goes to standard error)")
      ->check(notEmpty());
  command->callback([flags] {
    if (const int status = runReportingErrors("calibrate", [&] { runCalibrate(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
