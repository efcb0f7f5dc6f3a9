#include "tools/baize/bench_cushion_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/cushion_bench.h"
#include "tools/baize/cushion_param_flags.h"
#include "tools/baize/random_shots.h"

namespace baize::tools {
namespace {

constexpr int kDefaultPasses = 3;    // timed passes over the set; each impact keeps its best time
constexpr double kSpeedTarget = 20;  // exact default at least 20x faster than paper N=5000
constexpr double kAccuracyTarget = 1000;  // and at least 1000x more accurate

struct BenchFlags {
  std::string csv_path;
  int impacts = kDefaultBenchImpacts;
  int passes = kDefaultPasses;
  CushionParamFlags cushion_flags;  // default: the paper's snooker values
  std::optional<int> from_shots;    // given: the impacts of this many random single shots instead
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
  physics::CushionParams params = cushionParamsOf(flags.cushion_flags);
  // Opened first, so that an unwritable path fails before the measurement.
  std::optional<AtomicFile> csv;
  if (!flags.csv_path.empty()) csv.emplace(flags.csv_path, "--csv");

  std::vector<BenchInput> inputs;
  if (flags.from_shots) {
    const std::vector<physics::BallVelocity> impacts =
        cushionImpactsOf(randomSingleShots(*flags.from_shots), &params);
    for (const physics::BallVelocity& incoming : impacts) {
      inputs.push_back({incoming, std::hypot(incoming.v.x(), incoming.v.y()), true});
    }
    if (inputs.empty()) {
      rejectFlag("--from-shots", *flags.from_shots, "those shots meet no cushion; take more");
    }
    std::cout << "baize bench cushion: the " << inputs.size() << " cushion and jaw impacts of "
              << *flags.from_shots << " random single shot" << (*flags.from_shots == 1 ? "" : "s")
              << " (those of `baize bench shots`), "
              << "best time of " << flags.passes << " timed passes per impact\n";
  } else {
    inputs = seededBenchInputs(params.radius_m, flags.impacts);
    std::cout << "baize bench cushion: " << flags.impacts << " impacts (seed " << kBenchSeed
              << "; V0 in [0.1, 2.5] m/s, alpha in [1, 179] deg, topspin in [-2, 3] V0/R, "
              << "sidespin in [-3, 3] V0/R), best time of " << flags.passes
              << " timed passes per impact\n";
  }
  std::cout << "cushion: M " << physics::valueText(params.mass_kg) << " kg, R "
            << physics::valueText(params.radius_m) << " m, h "
            << physics::valueText(params.contact_height_m) << " m, e_e "
            << physics::valueText(params.restitution) << ", mu_w "
            << physics::valueText(params.cushion_friction) << ", mu_s "
            << physics::valueText(params.cloth_friction) << '\n';
  const std::string header = "solver,setting,median_ns,max_error";
  bool header_printed = false;
  const BenchReport report =
      runCushionBench(params, inputs, flags.passes, [&](const BenchRow& row) {
        if (!header_printed) {
          std::cout << header << '\n';
          header_printed = true;
        }
        std::cout << csvRow(row) << std::endl;  // flushed: the bench takes a while
      });
  std::cout << "reference: exact solver at tolerance " << kReferenceTolerance
            << "; it differs from the solution at tolerance " << kReferenceCheckTolerance
            << " by at most " << std::setprecision(3) << report.reference_check_error
            << " (same error measure)\n";

  const BenchRow& paper = rowLabelled(report, SolverKind::Paper, "N=5000");
  const BenchRow& exact = rowLabelled(report, SolverKind::Exact, "default");
  // The targets are set on the drawn sets; the impacts of play are scored against none.
  const bool targets = !flags.from_shots;
  printRatio("speed ratio (paper N=5000 median_ns / exact default median_ns)",
             paper.median_ns / exact.median_ns, targets ? kSpeedTarget : 0);
  printRatio("accuracy ratio (paper N=5000 max_error / exact default max_error)",
             paper.max_error / exact.max_error, targets ? kAccuracyTarget : 0);

  if (csv) {
    csv->stream() << header << '\n';
    for (const BenchRow& row : report.rows) csv->stream() << csvRow(row) << '\n';
    csv->commit();
    std::cout << "wrote " << flags.csv_path << '\n';
  }
}

}  // namespace

void addBenchCushionCommand(CLI::App& bench) {
  auto flags = std::make_shared<BenchFlags>();
  CLI::App* command = bench.add_subcommand(
      "cushion",
      "Time the paper and exact cushion solvers and measure their error against a "
      "converged reference, over one fixed seeded set of impacts (or the impacts of random shots)");
  command->add_option("--csv", flags->csv_path, "also write the table to this CSV file")
      ->check(notEmpty());
  command->add_option("--impacts", flags->impacts, "impacts in the set (a smoke run can use few)")
      ->capture_default_str();
  command->add_option("--repeat", flags->passes, "timed passes; each impact keeps its best time")
      ->capture_default_str();
  addCushionParamFlags(command, &flags->cushion_flags);
  CLI::Option* from_shots =
      command->add_option("--from-shots", flags->from_shots,
                          "score the impacts of this many of `baize bench shots`' random single "
                          "shots instead of the seeded sets (their table's cushion)");
  for (const char* name : {"--impacts", "--mass", "--radius", "--h", "--e", "--mu-w", "--mu-s"}) {
    from_shots->excludes(name);
  }
  command->callback([flags] {
    if (const int status = runReportingErrors("bench cushion", [&] { runBench(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
