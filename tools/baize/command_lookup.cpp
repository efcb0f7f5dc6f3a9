#include "tools/baize/command_lookup.h"

#include <algorithm>
#include <numeric>

#include "tools/baize/cli_errors.h"

namespace baize::tools {
namespace {

// Levenshtein distance: insertions, deletions and substitutions of single letters.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> namesOf(CLI::App& parent) {
  std::vector<std::string> names;
  for (const CLI::App* sub : parent.get_subcommands({})) names.push_back(sub->get_name());
  return names;
}

}  // namespace

std::string commandPath(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* parent = command.get_parent(); parent; parent = parent->get_parent()) {
    path = parent->get_name() + " " + path;
  }
  return path;
}

void addRefusedCommand(CLI::App& parent, const std::string& name, const std::string& description,
                       const std::string& why) {
  CLI::App* command = parent.add_subcommand(name, description);
  command->prefix_command();  // every word after the name is left unread
  command->set_help_flag();   // --help included: it is refused as the rest
  command->callback([command, why] { throw UsageError("'" + commandPath(*command) + "' " + why); });
}

CLI::App* subcommandNamed(CLI::App& parent, const std::string& name) {
  for (CLI::App* sub : parent.get_subcommands({}))
    if (sub->get_name() == name) return sub;
  return nullptr;
}

std::vector<std::string> nearestNames(CLI::App& parent, const std::string& typed) {
  std::vector<std::pair<std::size_t, std::string>> near;
  for (const std::string& name : namesOf(parent)) {
    const std::size_t d = editDistance(typed, name);
    if (3 * d <= std::max(typed.size(), name.size())) near.emplace_back(d, name);
  }
  std::sort(near.begin(), near.end());
  std::vector<std::string> names;
  for (const auto& [d, name] : near) names.push_back(name);
  return names;
}

std::string unknownCommandMessage(CLI::App& parent, const std::string& path,
                                  const std::string& typed) {
  std::string message = "unknown command '" + path + typed + "'";
  const std::vector<std::string> near = nearestNames(parent, typed);
  message += near.empty() ? "." : "; did you mean '" + path + near.front() + "'?";
  std::vector<std::string> all = namesOf(parent);
  std::sort(all.begin(), all.end());
  message += " The commands are:";
  for (const std::string& name : all) message += " " + path + name;
  return message;
}

void checkCommandWords(CLI::App& app, const std::vector<std::string>& words) {
  CLI::App* level = &app;
  std::string path;
  for (const std::string& word : words) {
    if (word.empty() || word[0] == '-') return;  // flags from here on
    CLI::App* sub = subcommandNamed(*level, word);
    if (!sub) throw CLI::ValidationError(unknownCommandMessage(*level, path, word));
    if (sub->get_subcommands({}).empty()) return;  // the rest are the command's own words
    level = sub;
    path += word + " ";
  }
}

}  // namespace baize::tools
