// baize: the table simulator's command-line program. Each subcommand lives in its own file pair
// (tools/baize/<name>_command.*) and registers itself on the App built here; the commands that
// only draw, and the drawing of the others' picture flags, come from picture_commands.h.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "tools/baize/batch_command.h"
#include "tools/baize/bench_accuracy_command.h"
#include "tools/baize/bench_cushion_command.h"
#include "tools/baize/bench_play_command.h"
#include "tools/baize/bench_shots_command.h"
#include "tools/baize/calibrate_command.h"
#include "tools/baize/check_command.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/command_lookup.h"
#include "tools/baize/cushion_command.h"
#include "tools/baize/picture_commands.h"
#include "tools/baize/plan_command.h"
#include "tools/baize/play_command.h"
#include "tools/baize/progress.h"
#include "tools/baize/simulate_command.h"
#include "tools/baize/standard_output.h"
#include "tools/baize/stress_command.h"
#include "tools/baize/sweep_command.h"

int main(int argc, char** argv) {
  using namespace baize::tools;
  CLI::App app{"Baize: an event-based pool and snooker table simulator", "baize"};
  app.require_subcommand(1, 1);
  // Null in a build without rendering: the commands then refuse their picture flags by name.
  const Drawing* drawing = renderedDrawing();

  addBatchCommand(app);
  addCalibrateCommand(app, drawing);
  addChartCommand(app);
  addCheckCommand(app, drawing);
  addCushionCommand(app);
  addPlanCommand(app, drawing);
  addPlayCommand(app, drawing);
  addSimulateCommand(app, drawing);
  addRenderCommand(app);
  addStressCommand(app);
  addSweepCommand(app, drawing);

  CLI::App* bench = app.add_subcommand("bench", "Measure the speed and accuracy of the models");
  bench->require_subcommand(1, 1);
  addBenchCushionCommand(*bench);
  addBenchShotsCommand(*bench);
#ifdef BAIZE_WITH_BOX2D  // it compares against Box2D: refused by name in a build without it
  addBenchAccuracyCommand(*bench);
#else
  addRefusedCommand(*bench, "accuracy",
                    "not in this build: it compares against Box2D (BAIZE_WITH_BOX2D=OFF)",
                    "compares against Box2D, and this baize was built without it "
                    "(BAIZE_WITH_BOX2D=OFF; Debian: libbox2d-dev)");
#endif
  addBenchRenderCommand(*bench);
  addBenchPlayCommand(*bench);

  addQuietFlag(app);
  app.set_version_flag("--version", std::string("baize ") + BAIZE_VERSION);
  app.footer("Run 'baize help COMMAND' (or 'baize COMMAND --help') for a command's flags.");

  std::vector<std::string> words(argv + 1, argv + argc);
  try {
    // "baize help [CMD ...]": the help of the command named (of baize itself with none).
    if (!words.empty() && words[0] == "help") {
      words.erase(words.begin());
      checkCommandWords(app, words);
      CLI::App* shown = &app;
      for (const std::string& word : words) {
        CLI::App* named = subcommandNamed(*shown, word);
        if (named == nullptr) {  // past a command that has no subcommands: not a command name
          throw UsageError("'baize help' takes command names only: '" + word +
                           "' is not a command of '" + commandPath(*shown) + "'");
        }
        shown = named;
      }
      std::cout << shown->help();
      return 0;
    }
    checkCommandWords(app, words);
    const ReportsToStandardError reports(outputFlagsOnStandardOutput(words));
    app.parse(argc, argv);
  } catch (const UsageError& refused) {
    std::cerr << "baize: error: " << refused.what() << '\n';
    return kExitUsage;
  } catch (const CLI::RuntimeError& failed) {  // a command that ran and reported its own error
    return failed.get_exit_code();
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) {  // --help: the help text is the output, so it must arrive
      const int status = app.exit(error);
      std::cout.flush();
      if (!std::cout) {
        std::cerr << "baize: error: standard output could not be written\n";
        return kExitFailure;
      }
      return status;
    }
    std::cerr << "baize: error: " << error.what() << "\nRun 'baize --help' for usage.\n";
    return kExitUsage;
  }
  return 0;
}
