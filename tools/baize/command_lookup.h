// Finding a command by the name a user typed: the subcommand named, or the nearest names for a
// message when none is ("unknown command 'simulat'; did you mean 'simulate'?").
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace baize::tools {

// "baize simulate", "baize bench render": the command as typed.
std::string commandPath(const CLI::App& command);

// A subcommand of `parent` that this build lacks: it keeps its name so that typing it says why it
// is missing rather than that it is unknown. It takes any words (--help included) and refuses them
// all with a UsageError "'baize ... NAME' <why>", before any work.
void addRefusedCommand(CLI::App& parent, const std::string& name, const std::string& description,
                       const std::string& why);

// The subcommand of `parent` named `name`, or null.
CLI::App* subcommandNamed(CLI::App& parent, const std::string& name);

// The names of `parent`'s subcommands closest to `typed` by edit distance (at most a third of the
// longer name's letters apart), nearest first; empty when none is that close.
std::vector<std::string> nearestNames(CLI::App& parent, const std::string& typed);

// "unknown command 'X'" with the nearest names suggested and the known ones listed, for the
// subcommand level under `parent` (`path` names it: "" or "bench ").
std::string unknownCommandMessage(CLI::App& parent, const std::string& path,
                                  const std::string& typed);

// Checks argv's command words before parsing: the first word (after "help") must name a
// subcommand, and under "bench" the second too. Throws CLI::ValidationError with
// unknownCommandMessage otherwise; words starting with '-' are flags, left to the parser.
void checkCommandWords(CLI::App& app, const std::vector<std::string>& words);

}  // namespace baize::tools
