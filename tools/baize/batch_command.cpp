#include "tools/baize/batch_command.h"

#include <CLI/CLI.hpp>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "engine/io/json_reader.h"
#include "engine/io/result_file.h"
#include "engine/io/scene.h"
#include "engine/play/shot_outcome.h"
#include "engine/play/shot_suite.h"
#include "engine/sim/cushion_solve_ahead.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/progress.h"
#include "tools/baize/thread_flag.h"

namespace baize::tools {
namespace {

// Lines read before they are run and written: bounds the memory and lets results stream out of a
// pipe, while giving every thread plenty of shots per chunk.
constexpr std::size_t kChunkLines = 4096;
// The longest input line read, bytes: a line holds one shot (a scene, with its table at most),
// far below this; an input with no line ends (/dev/zero) is refused instead of read until memory
// runs out.
constexpr std::size_t kMaxLineBytes = std::size_t{16} << 20;

// Reads one line (without its '\n') into *line: false at the end of the input with nothing read.
// Throws UsageError naming the input and the line when it is longer than kMaxLineBytes.
bool readLine(std::istream& in, const std::string& input_name, long number, std::string* line) {
  line->clear();
  std::streambuf* buffer = in.rdbuf();
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) return !line->empty();
    if (c == '\n') return true;
    if (line->size() == kMaxLineBytes) {
      throw UsageError("input " + input_name + ": line " + std::to_string(number) +
                       " is longer than " + std::to_string(kMaxLineBytes >> 20) +
                       " MiB, the most a line may be (one shot per line)");
    }
    line->push_back(static_cast<char>(c));
  }
}

struct BatchFlags {
  std::string input = "-";  // "-": standard input
  int threads = 0;          // 0: the hardware concurrency
};

struct InputLine {
  long number = 0;  // 1-based line number in the input
  std::string text;
};

// The scene of one line: a scene object, or {"scene": path or object, "shot": {...}}; either may
// carry an "id", which is echoed and otherwise ignored.
engine::Scene lineScene(nlohmann::json document, const std::string& source,
                        const std::string& folder) {
  engine::JsonReader(document, source);  // refuses anything but an object, naming the line
  document.erase("id");
  if (!document.contains("scene")) return engine::sceneFromJson(document, source);
  const engine::JsonReader reader(document, source);
  reader.requireKeys({"scene"}, {"shot"});
  nlohmann::json scene = document.at("scene");
  std::string scene_source = source;
  if (scene.is_string()) {
    scene_source = (std::filesystem::path(folder) / reader.text("scene")).string();
    scene = engine::JsonReader::parseFile(scene_source);
  } else if (!scene.is_object()) {
    reader.reject("scene",
                  "a scene object or the path of a scene file (relative to the input's "
                  "folder; standard input: the working directory)");
  }
  // The line's own shot replaces the scene's whole and is read where it stands (the line), so that
  // a refusal about it names the line, not the scene file.
  if (!reader.has("shot")) return engine::sceneFromJson(scene, scene_source);
  const engine::JsonReader own_shot = reader.object("shot");
  return engine::sceneFromJson(scene, scene_source, &own_shot);
}

// One result line; `failed` is set when the line could not be run.
std::string runLine(const InputLine& line, const std::string& input_name, const std::string& folder,
                    bool* failed) {
  const std::string source = input_name + ":" + std::to_string(line.number);
  std::optional<nlohmann::json> id;
  nlohmann::json out;
  try {
    const nlohmann::json document =
        engine::JsonReader::parseText(line.text, source, "each line must be one JSON object");
    if (document.is_object() && document.contains("id")) id = document.at("id");
    engine::Scene scene = lineScene(document, source, folder);
    const engine::SceneRun run = engine::runScene(scene);
    engine::ShotResult result = engine::shotResult(std::move(scene), run, /*with_recording=*/false);
    result.line = line.number;
    result.id = id;
    out = engine::resultJson(result);
    *failed = false;
  } catch (const std::exception& e) {
    // Not a result: the format and version say whose line it is, "error" that the shot failed.
    out = {{"format", engine::kResultFormat},
           {"version", engine::kResultVersion},
           {"line", line.number},
           {"error", e.what()}};
    if (id) out["id"] = *id;
    *failed = true;
  }
  // Replacing bytes that are not UTF-8 (a parse error quotes the raw input, a file name may hold
  // any bytes) rather than throwing: the line's result is written whatever it holds.
  return out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

int runBatch(const BatchFlags& flags) {
  const int threads = threadsOfFlag(flags.threads);
  const bool from_stdin = flags.input == "-";
  std::ifstream file;
  if (!from_stdin) {
    std::error_code error;
    if (std::filesystem::is_directory(flags.input, error)) {
      throw UsageError("input " + flags.input +
                       " is a directory, which is not allowed: it must be a file of JSON lines, "
                       "or - for standard input");
    }
    file.open(flags.input);
    if (!file) {
      throw UsageError("input " + flags.input +
                       " cannot be opened: it must be a readable file of JSON lines, or - for "
                       "standard input");
    }
  }
  std::istream& in = from_stdin ? std::cin : file;
  const std::string input_name = from_stdin ? "stdin" : flags.input;
  const std::string folder =
      from_stdin ? "" : std::filesystem::path(flags.input).parent_path().string();

  long number = 0, shots = 0, failures = 0;
  Progress progress("shots", 0);  // the input's length is not known ahead
  std::vector<InputLine> chunk;
  std::string text;
  bool more = true;
  while (more) {
    chunk.clear();
    while (chunk.size() < kChunkLines && (more = readLine(in, input_name, number + 1, &text))) {
      ++number;
      if (text.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank: no shot
      chunk.push_back({number, text});
    }
    std::vector<std::string> results(chunk.size());
    std::vector<char> failed(chunk.size(), 0);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
      for (std::size_t i = next++; i < chunk.size(); i = next++) {
        bool line_failed = false;
        results[i] = runLine(chunk[i], input_name, folder, &line_failed);
        failed[i] = line_failed;
        progress.advance();
      }
    };
    std::vector<std::thread> pool;
    const int used = std::min<int>(threads, static_cast<int>(chunk.size()));
    for (int t = 1; t < used; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      std::cout << results[i] << '\n';
      failures += failed[i];
    }
    shots += static_cast<long>(chunk.size());
    std::cout.flush();
  }
  if (!std::cout) throw std::runtime_error("standard output could not be written");
  if (failures > 0) {
    std::cerr << "baize batch: " << failures << " of " << shots
              << " lines failed (their result lines carry \"error\")\n";
    return kExitFailure;
  }
  return 0;
}

}  // namespace

void addBatchCommand(CLI::App& parent) {
  auto flags = std::make_shared<BatchFlags>();
  CLI::App* command = parent.add_subcommand(
      "batch", "Run shots given as JSON lines; one JSON result line per shot, in input order");
  command->add_option("input", flags->input,
                      "file of JSON lines (default -: standard input); docs/positional.md");
  command->add_option("--threads", flags->threads, kThreadsHelp);
  command->callback([flags] {
    int status = 0;
    if (const int error = runReportingErrors("batch", [&] { status = runBatch(*flags); })) {
      throw CLI::RuntimeError(error);
    }
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace baize::tools
