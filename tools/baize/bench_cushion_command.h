// `baize bench cushion`: the cushion solvers' speed and accuracy over one fixed set of impacts,
// as a table (solver,setting,median_ns,max_error) on stdout and optionally in a CSV file.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

// Adds "cushion" under `bench`, the parent of the benchmark subcommands.
void addBenchCushionCommand(CLI::App& bench);

}  // namespace baize::tools
