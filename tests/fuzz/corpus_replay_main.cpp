// The fuzz targets without libFuzzer: feeds every file of the given corpus folders (and files) to
// LLVMFuzzerTestOneInput, then a seeded number of mutations of them (bytes flipped, inserted,
// deleted, overwritten with edge bytes, files truncated and spliced). That is the "short fuzz run"
// of the normal test suite: no coverage guidance, but every target runs on every corpus input and
// on inputs near them with the normal compiler, deterministically.
//
// Usage: replay_fuzz_NAME [--mutations N] [--seed S] CORPUS_DIR_OR_FILE...
// Exits 1 when no input file is found (a missing corpus must not pass silently); a failing input
// aborts inside the target after printing which input it was.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

// libFuzzer's default -max_len for a corpus of small files; mutations never grow past it.
constexpr std::size_t kMaxInputBytes = 4096;

Bytes readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The input being run, named by the crash handler below (a fixed buffer: the handler may only call
// async-signal-safe functions).
char current_input[512] = "";

// Its bytes, written to kFailingInputFile by the handler so that a failing mutation can be rerun
// (and kept as a regression input).
const Bytes* current_bytes = nullptr;
constexpr char kFailingInputFile[] = "replay-failing-input.bin";

void nameInputAndDie(int signal_number) {
  static const char kPrefix[] = "replay: the failing input is ";
  static const char kSaved[] = ", saved as ";
  (void)!write(STDERR_FILENO, kPrefix, sizeof kPrefix - 1);
  (void)!write(STDERR_FILENO, current_input, strnlen(current_input, sizeof current_input));
  if (current_bytes != nullptr) {
    const int fd = open(kFailingInputFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      (void)!write(fd, current_bytes->data(), current_bytes->size());
      close(fd);
      (void)!write(STDERR_FILENO, kSaved, sizeof kSaved - 1);
      (void)!write(STDERR_FILENO, kFailingInputFile, sizeof kFailingInputFile - 1);
    }
  }
  (void)!write(STDERR_FILENO, "\n", 1);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void run(const Bytes& input, const std::string& name) {
  std::snprintf(current_input, sizeof current_input, "%s (%zu bytes)", name.c_str(), input.size());
  current_bytes = &input;
  LLVMFuzzerTestOneInput(input.data(), input.size());
  current_bytes = nullptr;
}

// One random edit of `input`, using `other` for splices.
Bytes mutate(Bytes input, const Bytes& other, std::mt19937_64& random) {
  auto below = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(random() % n); };
  static const std::uint8_t kEdgeBytes[] = {0x00, 0xff, 0x7f, 0x80, '0', '9', '-', 'e', '"',
                                            '[',  ']',  '{',  '}',  ',', ':', '.', 'n'};
  const int edits = 1 + static_cast<int>(below(4));
  for (int e = 0; e < edits; ++e) {
    switch (below(6)) {
      case 0:  // flip one bit
        if (!input.empty()) input[below(input.size())] ^= static_cast<std::uint8_t>(1u << below(8));
        break;
      case 1:  // overwrite a byte with one that matters to JSON or to number bits
        if (!input.empty()) {
          input[below(input.size())] = kEdgeBytes[below(sizeof kEdgeBytes)];
        }
        break;
      case 2:  // insert a byte
        if (input.size() < kMaxInputBytes) {
          input.insert(input.begin() + below(input.size() + 1),
                       kEdgeBytes[below(sizeof kEdgeBytes)]);
        }
        break;
      case 3:  // delete a run of bytes
        if (!input.empty()) {
          const std::size_t at = below(input.size());
          const std::size_t n = std::min<std::size_t>(1 + below(8), input.size() - at);
          input.erase(input.begin() + at, input.begin() + at + n);
        }
        break;
      case 4:  // truncate
        input.resize(below(input.size() + 1));
        break;
      default: {  // splice: a prefix of this input, a suffix of the other
        const std::size_t cut = below(input.size() + 1);
        const std::size_t from = below(other.size() + 1);
        input.resize(cut);
        input.insert(input.end(), other.begin() + from, other.end());
        if (input.size() > kMaxInputBytes) input.resize(kMaxInputBytes);
        break;
      }
    }
  }
  return input;
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 0;
  std::uint64_t seed = 1;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mutations" && i + 1 < argc) {
      mutations = std::stol(argv[++i]);
      continue;
    }
    if (arg == "--seed" && i + 1 < argc) {
      seed = std::stoull(argv[++i]);
      continue;
    }
    const std::filesystem::path path(arg);
    if (std::filesystem::is_directory(path)) {
      for (const auto& entry : std::filesystem::directory_iterator(path)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
      }
    } else if (std::filesystem::is_regular_file(path)) {
      files.push_back(path);
    } else {
      std::fprintf(stderr, "%s: no such corpus file or folder\n", arg.c_str());
      return 1;
    }
  }
  std::sort(files.begin(), files.end());  // the same order on every machine
  if (files.empty()) {
    std::fprintf(stderr, "no corpus input given: the replay would test nothing\n");
    return 1;
  }
  for (int signal_number : {SIGABRT, SIGSEGV, SIGFPE, SIGBUS, SIGILL}) {
    std::signal(signal_number, nameInputAndDie);
  }
  std::vector<Bytes> corpus;
  for (const auto& file : files) {
    corpus.push_back(readFile(file));
    run(corpus.back(), file.string());
  }
  std::mt19937_64 random(seed);
  for (long m = 0; m < mutations; ++m) {
    const std::size_t a = random() % corpus.size(), b = random() % corpus.size();
    const Bytes mutation = mutate(corpus[a], corpus[b], random);
    run(mutation, "mutation " + std::to_string(m) + " of " + files[a].filename().string());
  }
  std::printf("%zu corpus inputs and %ld mutations ran without a failure\n", corpus.size(),
              mutations);
  return 0;
}
