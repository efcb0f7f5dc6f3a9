#include "tools/baize/check_command.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "engine/play/shot_suite.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/drawing.h"
#include "tools/baize/output_folder.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

// Samples per case allowed with --noise: enough for any confidence interval anyone needs, and a
// bound that keeps a typo from running for days.
constexpr int kMaxNoiseSamples = 10000000;

struct CheckFlags {
  std::string suite;
  std::string junit_path;
  std::string png_dir;    // pictures of the failing cases, when set
  int noise_samples = 0;  // 0: no noise run
  std::uint64_t seed = 1;
  engine::ExecutionNoise noise;  // sigmas; the flags below set them in friendlier units
  double tip_sigma_mm = 0.5;
  const Drawing* drawing = nullptr;  // draws --png-dir; none in a build without rendering
};

std::string expectationText(const engine::ExpectationResult& r) {
  return r.key + (r.met ? " ok (" + r.measured + ")"
                        : " FAILED (expected " + r.expected + "; measured " + r.measured + ")");
}

std::string caseLine(const engine::CaseResult& result) {
  std::string line = std::string(result.passed ? "PASS " : "FAIL ") + result.name;
  if (!result.error.empty()) return line + ": the shot did not run: " + result.error;
  for (const engine::ExpectationResult& r : result.expectations) line += " | " + expectationText(r);
  return line;
}

std::string probabilityText(const engine::ProbabilityEstimate& p) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << p.probability << " [" << p.low << ", " << p.high
      << "] (" << p.successes << "/" << p.samples << ")";
  return out.str();
}

// A case name as a file name: characters other than letters, digits, '-', '_' and '.' become '_'
// (names are free text; a '/' must not make a folder).
std::string fileNameOf(const std::string& case_name) {
  std::string name = case_name;
  for (char& c : name) {
    const bool safe =
        std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    if (!safe) c = '_';
  }
  if (name.empty() || name == "." || name == "..") name = "case" + name;
  return name;
}

// Draws a failing case's shot with its expected regions to DIR/<case>.png.
// The pictures of failing cases: case_<case>.png.
const OutputFileNames kCasePictureNames{"case_", ".png"};

void drawFailingCase(const engine::SuiteCase& c, const std::string& dir, ShotPainter& painter) {
  const engine::SceneRun run = engine::runScene(c.scene, true);
  std::vector<engine::CueBallRegion> regions;
  for (const engine::Expectation& e : c.expectations) {
    if (e.kind == engine::Expectation::Kind::CueBallStopsIn) regions.push_back(e.region);
  }
  const std::string path =
      (std::filesystem::path(dir) / (kCasePictureNames.prefix + fileNameOf(c.name) +
                                     kCasePictureNames.suffix))
          .string();
  painter.write(c.scene, run, regions, path);
  note(std::cout) << "  picture: " << path << "\n";
}

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters other than tab and newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') {
          out += ' ';
        } else {
          out += c;
        }
    }
  }
  return out;
}

int runCheck(const CheckFlags& flags) {
  if (flags.noise_samples < 0 || flags.noise_samples > kMaxNoiseSamples) {
    rejectFlag("--noise", flags.noise_samples,
               "a number of samples per case in [0, " + std::to_string(kMaxNoiseSamples) + "]");
  }
  engine::ExecutionNoise noise = flags.noise;
  // Each sigma checked as its flag gives it (the engine's own check names the quantity in SI
  // units).
  for (const auto& [flag, value] :
       {std::pair<const char*, double>{"--sigma-tip-mm", flags.tip_sigma_mm},
        {"--sigma-elevation-deg", noise.elevation_sigma_deg},
        {"--sigma-aim-deg", noise.aim_sigma_deg},
        {"--sigma-speed-mps", noise.speed_sigma_mps}}) {
    requireFiniteFlag(flag, value);
    if (value < 0) rejectFlag(flag, value, "it must be >= 0");
  }
  noise.tip_offset_sigma_m = flags.tip_sigma_mm / 1000;
  engine::validateExecutionNoise(noise);
  std::unique_ptr<AtomicFile> junit;
  if (!flags.junit_path.empty()) junit = std::make_unique<AtomicFile>(flags.junit_path, "--junit");
  const engine::Suite suite = engine::loadSuite(flags.suite);
  std::unique_ptr<ShotPainter> painter;
  if (!flags.png_dir.empty()) {
    prepareOutputFolder("--png-dir", flags.png_dir, kCasePictureNames);
    painter = flags.drawing->shotPainter();
  }

  std::cout << "suite: " << flags.suite << " (" << suite.cases.size() << " cases"
            << (flags.noise_samples > 0
                    ? ", " + std::to_string(flags.noise_samples) + " noisy samples each, seed " +
                          std::to_string(flags.seed)
                    : "")
            << ")\n";
  int passed = 0, failed = 0, errors = 0;
  std::ostringstream cases_xml;
  Progress progress("cases", static_cast<long>(suite.cases.size()));
  for (std::size_t i = 0; i < suite.cases.size(); ++i, progress.advance()) {
    const engine::SuiteCase& c = suite.cases[i];
    const auto start = std::chrono::steady_clock::now();
    const engine::CaseResult result = engine::runCase(c);
    const std::string line = caseLine(result);
    std::cout << line << "\n";
    // A case whose shot did not run has nothing to draw.
    if (painter && !result.passed && result.error.empty())
      drawFailingCase(c, flags.png_dir, *painter);
    std::string noise_lines;
    if (flags.noise_samples > 0) {
      const engine::NoisyCaseResult noisy =
          engine::sampleCase(c, noise, flags.noise_samples, flags.seed, i);
      noise_lines += "  noise: whole case " + probabilityText(noisy.whole_case);
      if (noisy.miscues > 0) noise_lines += ", " + std::to_string(noisy.miscues) + " miscues";
      if (noisy.failed_runs > 0) {
        noise_lines += ", " + std::to_string(noisy.failed_runs) + " runs over the event budget";
      }
      noise_lines += "\n";
      for (std::size_t k = 0; k < c.expectations.size(); ++k) {
        noise_lines += "  noise: " + std::string(engine::expectationKey(c.expectations[k].kind)) +
                       " " + probabilityText(noisy.expectations[k]) + "\n";
      }
      std::cout << noise_lines;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    (result.passed ? passed : failed) += 1;
    errors += !result.error.empty();
    cases_xml << "  <testcase classname=\""
              << xmlEscaped(std::filesystem::path(flags.suite).stem().string()) << "\" name=\""
              << xmlEscaped(c.name) << "\" time=\"" << std::fixed << std::setprecision(6) << seconds
              << "\">\n";
    if (!result.error.empty()) {
      cases_xml << "    <error message=\"" << xmlEscaped(result.error) << "\"/>\n";
    } else if (!result.passed) {
      std::string message;
      for (const engine::ExpectationResult& r : result.expectations) {
        if (!r.met) message += (message.empty() ? "" : "; ") + expectationText(r);
      }
      cases_xml << "    <failure message=\"" << xmlEscaped(message) << "\"/>\n";
    }
    cases_xml << "    <system-out>" << xmlEscaped(line + "\n" + noise_lines) << "</system-out>\n"
              << "  </testcase>\n";
  }
  std::cout << passed << " passed, " << failed << " failed\n";
  if (junit) {
    junit->stream() << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                    << "<testsuite name=\"" << xmlEscaped(flags.suite) << "\" tests=\""
                    << suite.cases.size() << "\" failures=\"" << failed - errors << "\" errors=\""
                    << errors << "\">\n"
                    << cases_xml.str() << "</testsuite>\n";
    junit->commit();
  }
  return failed > 0 ? kExitFailure : 0;
}

}  // namespace

void addCheckCommand(CLI::App& parent, const Drawing* drawing) {
  auto flags = std::make_shared<CheckFlags>();
  flags->drawing = drawing;
  CLI::App* command = parent.add_subcommand(
      "check",
      "Run a shot suite: pass/fail per case with the measured values (docs/positional.md)");
  command->add_option("suite", flags->suite, "the suite file (JSON)")->required();
  command->add_option("--junit", flags->junit_path, "also write a JUnit XML report here")
      ->check(notEmpty());
  needsDrawing(*command,
               command
                   ->add_option("--png-dir", flags->png_dir,
                                "draw each failing case's shot with its expected region to "
                                "DIR/case_<case>.png"),
               drawing)
      ->check(notEmpty());
  CLI::Option* noise =
      command->add_option("--noise", flags->noise_samples,
                          "also run N samples of each case with execution error and report the "
                          "probability of each expectation (pass/fail stays the noise-free shot's)");
  // The execution error's flags do nothing without samples: CLI11 refuses them alone, naming both.
  command->add_option("--seed", flags->seed, "seed of the execution error (default 1)")
      ->check(unsigned64())
      ->needs(noise);
  command
      ->add_option("--sigma-tip-mm", flags->tip_sigma_mm,
                   "execution error on each tip offset, mm (default 0.5)")
      ->needs(noise);
  command
      ->add_option("--sigma-elevation-deg", flags->noise.elevation_sigma_deg,
                   "execution error on the elevation, deg (default 0.1)")
      ->needs(noise);
  command
      ->add_option("--sigma-aim-deg", flags->noise.aim_sigma_deg,
                   "execution error on the aim, deg (default 0.125)")
      ->needs(noise);
  command
      ->add_option("--sigma-speed-mps", flags->noise.speed_sigma_mps,
                   "execution error on the cue speed, m/s (default 0.075)")
      ->needs(noise);
  command->callback([flags] {
    int status = 0;
    if (const int error = runReportingErrors("check", [&] { status = runCheck(*flags); })) {
      throw CLI::RuntimeError(error);
    }
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace baize::tools
