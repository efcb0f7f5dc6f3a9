#include "tools/baize/bench_cushion_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/io/scene.h"
#include "engine/play/random_shots.h"
#include "physics/cushion_tabulated_solver.h"
#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/cushion_bench.h"
#include "tools/baize/cushion_param_flags.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

constexpr int kDefaultPasses = 3;    // timed passes over the set; each impact keeps its best time
constexpr double kSpeedTarget = 20;  // exact default at least 20x faster than paper N=5000
constexpr double kAccuracyTarget = 1000;  // and at least 1000x more accurate

constexpr double kDegreesPerRadian = 180 / M_PI;

// The spinning and grippy sets' seed unless --seed gives another.
constexpr std::uint64_t kDefaultPromiseSetSeed = 1;

struct BenchFlags {
  std::string csv_path;
  int impacts = kDefaultBenchImpacts;
  int passes = kDefaultPasses;
  CushionParamFlags cushion_flags;    // default: the paper's snooker values
  std::optional<int> from_shots;      // given: the impacts of this many random single shots instead
  std::string from_scene;             // given: the impacts of this scene's shot instead
  std::string set = "drawn";          // drawn (the wide and rolling sets), spinning or grippy
  std::optional<std::uint64_t> seed;  // of the spinning or grippy set
  bool repeat_given = false;          // --repeat on the command line (those sets are not timed)
  bool frictions_given = false;       // --mu-w or --mu-s (the grippy set draws its own)
};

std::string csvRow(const BenchRow& row) {
  std::ostringstream out;
  out << solverName(row.setting.kind) << ',' << settingLabel(row.setting) << ',' << std::fixed
      << std::setprecision(1) << row.median_ns << ',' << physics::valueText(row.max_error);
  return out.str();
}

const BenchRow& rowLabelled(const BenchReport& report, SolverKind kind, const std::string& label) {
  for (const BenchRow& row : report.rows) {
    if (row.setting.kind == kind && settingLabel(row.setting) == label) return row;
  }
  throw std::logic_error("bench cushion: no row " + solverName(kind) + " " + label);
}

// target 0: none (the ratio alone).
void printRatio(const std::string& what, double ratio, double target) {
  std::cout << what << ": " << std::setprecision(3) << ratio;
  if (target > 0)
    std::cout << " (target >= " << target << ", " << (ratio >= target ? "met" : "NOT met") << ')';
  std::cout << '\n';
}

// The cushion in use, as every mode names it before its measurement (`frictions_drawn`: the grippy
// set's, drawn per impact).
void printCushion(const physics::CushionParams& params, bool frictions_drawn) {
  std::cout << "cushion: M " << physics::valueText(params.mass_kg) << " kg, R "
            << physics::valueText(params.radius_m) << " m, h "
            << physics::valueText(params.contact_height_m) << " m, e_e "
            << physics::valueText(params.restitution)
            << (frictions_drawn ? std::string(", mu_w and mu_s drawn per impact")
                                : ", mu_w " + physics::valueText(params.cushion_friction) +
                                      ", mu_s " + physics::valueText(params.cloth_friction))
            << '\n';
}

// How far the reference lies from the solution at the looser check tolerance.
void printReferenceCheck(double check_error) {
  std::cout << "reference: exact solver at tolerance " << kReferenceTolerance
            << "; it differs from the solution at tolerance " << kReferenceCheckTolerance
            << " by at most " << std::setprecision(3) << check_error << " (same error measure)\n";
}

// A small value as people write it: "1e-9", not the stream's "1e-09".
std::string exponentText(double value) {
  std::ostringstream text;
  text << std::setprecision(3) << value;
  std::string s = text.str();
  const std::size_t e = s.find('e');
  if (e != std::string::npos) {
    std::size_t digits = e + 2;  // after the sign
    while (digits + 1 < s.size() && s[digits] == '0') s.erase(digits, 1);
  }
  return s;
}

// The exact solver's promise on the exact default's row (every mode prints it).
// `impacts`: every impact scored (in the drawn mode, the wide and the rolling set).
void printPromise(const BenchRow& exact, int impacts) {
  std::ostringstream line;
  line << "exact default: " << std::fixed << std::setprecision(1) << exact.evaluations_per_impact
       << " evaluations per impact; " << exact.above_half_promise << " of " << impacts
       << " impacts above " << exponentText(kHalfPromiseShare * physics::kExactPromise) << " V0, "
       << exact.above_promise << " above the promised " << exponentText(physics::kExactPromise)
       << " V0 (" << (exact.above_promise == 0 ? "kept" : "NOT kept") << ")\n";
  std::cout << line.str();
}

// The default path's promise line (its median time only where it was timed).
void printTabulatedPromise(const BenchRow& tabulated, std::size_t impacts) {
  const bool kept = tabulated.max_error <= physics::kTabulatedPathPromise;
  std::cout << "tabulated default (the default path): " << tabulated.table_answers << " of "
            << impacts << " impacts answered from the table, the rest solved exactly at tolerance "
            << tabulated.setting.exact_tolerance;
  const std::size_t solved = impacts - static_cast<std::size_t>(tabulated.table_answers);
  const double evaluations = tabulated.evaluations_per_impact * static_cast<double>(impacts);
  if (solved > 0 && evaluations > 0) {  // their cost: the table's answers take no rate evaluations
    std::cout << " (" << std::setprecision(4) << evaluations / static_cast<double>(solved)
              << " rate evaluations each; the " << tabulated.stick_impacts
              << " with a stick phase take " << std::setprecision(3)
              << 100 * tabulated.stick_evaluations / evaluations << " % of them)";
  }
  std::cout << "; " << std::setprecision(3);
  if (tabulated.median_ns > 0) std::cout << tabulated.median_ns << " ns median; ";
  std::cout << "largest error " << tabulated.max_error << " V0, 99.9th percentile "
            << tabulated.p999_error << " V0; promised "
            << exponentText(physics::kTabulatedPathPromise) << " V0 ("
            << (kept ? "kept" : "NOT kept") << ")\n";
}

// --set spinning or grippy: the exact solver at its default against the reference, no timing.
void runPromiseSet(const BenchFlags& flags, const physics::CushionParams& params,
                   std::optional<AtomicFile>* csv) {
  const std::uint64_t seed = flags.seed.value_or(kDefaultPromiseSetSeed);
  const bool spinning = flags.set == "spinning";
  const std::vector<BenchInput> inputs =
      spinning ? spinningBenchInputs(params.radius_m, flags.impacts, seed)
               : grippyBenchInputs(params, flags.impacts, seed);
  std::ostringstream draws;
  if (spinning) {
    draws << "spin about each axis in [" << -kSpinningSpin_k << ", " << kSpinningSpin_k << "] V0/R";
  } else {
    draws << "mu_s in [" << kGrippyClothFrictionLow << ", " << kGrippyClothFrictionHigh
          << "], mu_w in [0, " << kGrippyCushionFrictionHigh << "], topspin in ["
          << kGrippyTopspinLow_k << ", " << kGrippyTopspinHigh_k << "] V0/R, sidespin in ["
          << -kGrippySidespin_k << ", " << kGrippySidespin_k << "] V0/R";
  }
  std::cout << "baize bench cushion: the " << flags.set << " set, " << flags.impacts
            << " impacts (seed " << seed << "; V0 in [0.1, 2.5] m/s, alpha in [1, 179] deg, "
            << draws.str() << "), the exact solver at its default tolerance, not timed\n";
  printCushion(params, /*frictions_drawn=*/!spinning);
  const PromiseReport report = scorePromise(params, inputs);
  const std::string header =
      "set,impacts,evaluations_per_impact,above_half_promise,"
      "above_promise,max_error";
  std::ostringstream row;
  row << flags.set << ',' << inputs.size() << ',' << std::fixed << std::setprecision(2)
      << report.row.evaluations_per_impact << ',' << report.row.above_half_promise << ','
      << report.row.above_promise << ',' << physics::valueText(report.row.max_error);
  std::cout << header << '\n' << row.str() << '\n';
  printPromise(report.row, static_cast<int>(inputs.size()));
  printTabulatedPromise(report.tabulated, inputs.size());
  const BenchInput& worst = inputs[report.worst];
  const physics::CushionParams& own = worst.params ? *worst.params : params;
  const double spin_unit = worst.speed_mps / own.radius_m;  // V0 / R
  std::cout << "largest error: impact " << report.worst << ", V0 "
            << physics::valueText(worst.speed_mps) << " m/s, alpha "
            << physics::valueText(std::atan2(worst.incoming.v.y(), worst.incoming.v.x()) *
                                  kDegreesPerRadian)
            << " deg, spin (" << physics::valueText(worst.incoming.w.x() / spin_unit) << ", "
            << physics::valueText(worst.incoming.w.y() / spin_unit) << ", "
            << physics::valueText(worst.incoming.w.z() / spin_unit) << ") V0/R, mu_w "
            << physics::valueText(own.cushion_friction) << ", mu_s "
            << physics::valueText(own.cloth_friction) << '\n';
  if (worst.shot) {  // the same impact, bit for bit, from `baize cushion`
    std::cout << "the same impact: baize cushion --speed "
              << physics::valueText(worst.shot->speed_mps) << " --angle "
              << physics::valueText(worst.shot->angle_deg) << " --topspin "
              << physics::valueText(worst.shot->topspin_k) << " --sidespin "
              << physics::valueText(worst.shot->sidespin_k) << " --mass "
              << physics::valueText(own.mass_kg) << " --radius " << physics::valueText(own.radius_m)
              << " --h " << physics::valueText(own.contact_height_m) << " --e "
              << physics::valueText(own.restitution) << " --mu-w "
              << physics::valueText(own.cushion_friction) << " --mu-s "
              << physics::valueText(own.cloth_friction) << '\n';
  }
  printReferenceCheck(report.reference_check_error);
  if (*csv) {
    (*csv)->stream() << header << '\n' << row.str() << '\n';
    (*csv)->commit();
    note(std::cout) << "wrote " << flags.csv_path << '\n';
  }
}

void runBench(const BenchFlags& flags) {
  if (flags.impacts < 1 || flags.impacts > kMaxBenchCount) {
    rejectFlag("--impacts", flags.impacts, kBenchCountAllowed);
  }
  if (flags.passes < 1 || flags.passes > kMaxBenchCount) {
    rejectFlag("--repeat", flags.passes, kBenchCountAllowed);
  }
  if (flags.from_shots && (*flags.from_shots < 1 || *flags.from_shots > kMaxBenchCount)) {
    rejectFlag("--from-shots", *flags.from_shots, kBenchCountAllowed);
  }
  if (flags.repeat_given && flags.set != "drawn") {
    throw UsageError("--repeat times the drawn sets; the " + flags.set + " set is not timed");
  }
  if (flags.seed && flags.set == "drawn") {
    throw UsageError(
        "--seed draws the spinning or grippy set (--set spinning or --set grippy); "
        "the drawn sets' seeds are fixed");
  }
  if (flags.frictions_given && flags.set == "grippy") {
    throw UsageError("--mu-w and --mu-s: the grippy set draws its own for every impact");
  }
  physics::CushionParams params = cushionParamsOf(flags.cushion_flags);
  if (flags.set == "grippy") {
    try {
      validateGrippyCushion(params);
    } catch (const std::invalid_argument& refused) {
      throw UsageError(
          std::string("the grippy set draws mu_w up to ") +
          physics::valueText(kGrippyCushionFrictionHigh) + " and mu_s up to " +
          physics::valueText(kGrippyClothFrictionHigh) +
          ", which this cushion (--mass, --radius, --h, --e) does not allow: " + refused.what());
    }
  }
  // Opened first, so that an unwritable path fails before the measurement.
  std::optional<AtomicFile> csv;
  if (!flags.csv_path.empty()) csv.emplace(flags.csv_path, "--csv");
  if (flags.set != "drawn") {
    runPromiseSet(flags, params, &csv);
    return;
  }

  std::vector<BenchInput> inputs;
  const auto impactsOfPlay = [&](const std::vector<physics::BallVelocity>& impacts) {
    for (const physics::BallVelocity& incoming : impacts) {
      inputs.push_back(
          {incoming, std::hypot(incoming.v.x(), incoming.v.y()), true, std::nullopt, std::nullopt});
    }
  };
  if (flags.from_shots) {
    impactsOfPlay(engine::cushionImpactsOf(engine::randomSingleShots(*flags.from_shots), &params));
    if (inputs.empty()) {
      rejectFlag("--from-shots", *flags.from_shots, "those shots meet no cushion; take more");
    }
    std::cout << "baize bench cushion: the " << inputs.size() << " cushion and jaw impacts of "
              << *flags.from_shots << " random single shot" << (*flags.from_shots == 1 ? "" : "s")
              << " (those of `baize bench shots`), "
              << "best time of " << flags.passes << " timed passes per impact\n";
  } else if (!flags.from_scene.empty()) {
    const engine::Scene scene = engine::loadScene(flags.from_scene);
    try {
      impactsOfPlay(engine::cushionImpactsOfScene(scene, &params));
    } catch (const std::invalid_argument& refused) {
      throw UsageError("--from-scene " + flags.from_scene + ": " + refused.what());
    }
    if (inputs.empty()) {
      throw UsageError("--from-scene " + flags.from_scene +
                       ": its shot meets no cushion; the scene must have cushion or jaw impacts");
    }
    std::cout << "baize bench cushion: the " << inputs.size() << " cushion and jaw impacts of "
              << flags.from_scene << ", best time of " << flags.passes
              << " timed passes per impact\n";
  } else {
    inputs = seededBenchInputs(params.radius_m, flags.impacts);
    std::cout << "baize bench cushion: " << flags.impacts << " impacts (seed " << kBenchSeed
              << "; V0 in [0.1, 2.5] m/s, alpha in [1, 179] deg, topspin in [-2, 3] V0/R, "
              << "sidespin in [-3, 3] V0/R), best time of " << flags.passes
              << " timed passes per impact\n";
  }
  printCushion(params, /*frictions_drawn=*/false);
  const std::string header = "solver,setting,median_ns,max_error";
  bool header_printed = false;
  Progress progress("solver settings", static_cast<long>(benchSettings().size()));
  const BenchReport report =
      runCushionBench(params, inputs, flags.passes, [&](const BenchRow& row) {
        progress.advance();
        if (!header_printed) {
          std::cout << header << '\n';
          header_printed = true;
        }
        std::cout << csvRow(row) << std::endl;  // flushed: the bench takes a while
      });
  printReferenceCheck(report.reference_check_error);

  const BenchRow& paper = rowLabelled(report, SolverKind::Paper, "N=5000");
  const BenchRow& exact = rowLabelled(report, SolverKind::Exact, "default");
  // The targets are set on the drawn sets; the impacts of play are scored against none.
  const bool targets = !flags.from_shots && flags.from_scene.empty();
  printRatio("speed ratio (paper N=5000 median_ns / exact default median_ns)",
             paper.median_ns / exact.median_ns, targets ? kSpeedTarget : 0);
  printRatio("accuracy ratio (paper N=5000 max_error / exact default max_error)",
             paper.max_error / exact.max_error, targets ? kAccuracyTarget : 0);
  printPromise(exact, static_cast<int>(inputs.size()));
  printTabulatedPromise(rowLabelled(report, SolverKind::Tabulated, "default"), inputs.size());

  if (csv) {
    csv->stream() << header << '\n';
    for (const BenchRow& row : report.rows) csv->stream() << csvRow(row) << '\n';
    csv->commit();
    note(std::cout) << "wrote " << flags.csv_path << '\n';
  }
}

}  // namespace

void addBenchCushionCommand(CLI::App& bench) {
  auto flags = std::make_shared<BenchFlags>();
  CLI::App* command = bench.add_subcommand(
      "cushion",
      "Time the paper and exact cushion solvers and measure their error against a "
      "converged reference, over one fixed seeded set of impacts (or the impacts of random shots); "
      "or check the exact solver's promise alone on a seeded spinning or grippy set");
  command->add_option("--csv", flags->csv_path, "also write the table to this CSV file")
      ->check(notEmpty());
  command->add_option("--impacts", flags->impacts, "impacts in the set (a smoke run can use few)")
      ->capture_default_str();
  CLI::Option* repeat =
      command
          ->add_option("--repeat", flags->passes, "timed passes; each impact keeps its best time")
          ->capture_default_str();
  addCushionParamFlags(command, &flags->cushion_flags);
  CLI::Option* from_shots =
      command->add_option("--from-shots", flags->from_shots,
                          "score the impacts of this many of `baize bench shots`' random single "
                          "shots instead of the seeded sets (their table's cushion)");
  CLI::Option* from_scene =
      command
          ->add_option("--from-scene", flags->from_scene,
                       "score the impacts of this scene's shot (a break, say) instead of the "
                       "seeded sets (its cushion, overrides included)")
          ->check(notEmpty());
  CLI::Option* set =
      command
          ->add_option("--set", flags->set,
                       "drawn: the wide and rolling sets, timed; spinning: spin about every axis; "
                       "grippy: grippy cushions and cloth (these two score the exact solver's "
                       "promise only, untimed)")
          ->check(CLI::IsMember({"drawn", "spinning", "grippy"}))
          ->capture_default_str();
  command
      ->add_option("--seed", flags->seed,
                   "seed of the spinning or grippy set (default " +
                       std::to_string(kDefaultPromiseSetSeed) + ")")
      ->check(unsigned64());
  for (const char* name : {"--impacts", "--mass", "--radius", "--h", "--e", "--mu-w", "--mu-s"}) {
    from_shots->excludes(name);
    from_scene->excludes(name);
  }
  from_shots->excludes(set);
  from_scene->excludes(set);
  from_scene->excludes(from_shots);
  command->callback([flags, repeat, command] {
    flags->repeat_given = repeat->count() > 0;
    flags->frictions_given =
        command->get_option("--mu-w")->count() > 0 || command->get_option("--mu-s")->count() > 0;
    if (const int status = runReportingErrors("bench cushion", [&] { runBench(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
