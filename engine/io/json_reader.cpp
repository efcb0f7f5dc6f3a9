#include "engine/io/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "physics/value_text.h"

namespace baize::engine {
namespace {

// Documents nested deeper than this are refused: the files here nest a few levels, and writing a
// value back into a message recurses once per level (tens of thousands overflow the stack).
constexpr int kMaxDepth = 64;
// A value quoted in a message is cut to this many characters (a huge value would drown it).
constexpr std::size_t kMaxQuotedChars = 200;

// `text` as a message shows it: cut after kMaxQuotedChars, saying how long it was (`length`).
std::string cutForMessage(const std::string& text, std::size_t length) {
  if (text.size() <= kMaxQuotedChars) return text;
  return text.substr(0, kMaxQuotedChars) + "... (" + std::to_string(length) + " characters)";
}

std::string typeName(const nlohmann::json& value) { return value.type_name(); }

// A key as a message shows it in a path: control characters (a NUL would end the message) as
// \uXXXX, and a long key cut, saying how long it was.
std::string keyText(const std::string& key) {
  std::string text;
  for (const char c : key) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(c));
      text += escaped;
    } else {
      text += c;
    }
  }
  return cutForMessage(text, key.size());
}

// A parser callback that refuses a key appearing twice in one object, naming its path in the
// document ("balls.cue", "cases[2].scene.shot"). It follows the parse with a stack of the open
// objects and arrays: an object remembers its keys so far, an array the index of its current
// element.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(std::string source) : source_(std::move(source)) {}

  bool operator()(int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (depth >= kMaxDepth) {
          throw std::invalid_argument(source_ + ": objects and arrays nested more than " +
                                      std::to_string(kMaxDepth) + " levels deep are not allowed");
        }
        startElement();
        open_.push_back({event == Event::object_start, {}, "", -1});
        break;
      case Event::object_end:
      case Event::array_end:
        open_.pop_back();
        break;
      case Event::key: {
        Container& object = open_.back();
        object.current_key = parsed.get<std::string>();
        if (!object.keys.insert(object.current_key).second) {
          throw std::invalid_argument(source_ + ": " + path() +
                                      " appears twice, which is not allowed: each key may "
                                      "appear only once in an object");
        }
        break;
      }
      case Event::value:
        startElement();
        break;
    }
    return true;  // keep everything
  }

 private:
  struct Container {
    bool is_object;
    std::set<std::string> keys;  // objects: the keys so far
    std::string current_key;     // objects: the key being read
    long index;                  // arrays: the element being read
  };

  // A value, object or array begins: inside an array it is the next element.
  void startElement() {
    if (!open_.empty() && !open_.back().is_object) ++open_.back().index;
  }

  // The path to the key being read, as JsonReader writes paths.
  std::string path() const {
    std::string text;
    for (const Container& c : open_) {
      if (c.is_object) {
        text += (text.empty() ? "" : ".") + keyText(c.current_key);
      } else {
        text += "[" + std::to_string(c.index) + "]";
      }
    }
    return text;
  }

  std::string source_;
  std::vector<Container> open_;
};

nlohmann::json parseStrictly(const std::string& text, const std::string& source,
                             const std::string& allowed) {
  // The parser would take a NUL byte for the end of the text and ignore what follows.
  if (const auto nul = text.find('\0'); nul != std::string::npos) {
    throw std::invalid_argument(source + ": a NUL byte at offset " + std::to_string(nul) +
                                " is not allowed: " + allowed);
  }
  try {
    return nlohmann::json::parse(text, DuplicateKeyCheck(source));
  } catch (const nlohmann::json::exception& error) {
    // Parse errors and numbers too large for a double (1e999) alike.
    throw std::invalid_argument(source + ": not valid JSON (" + error.what() +
                                ") is not allowed: " + allowed);
  }
}

}  // namespace

JsonReader::JsonReader(const nlohmann::json& object, std::string source, std::string path)
    : object_(object), source_(std::move(source)), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw std::invalid_argument(source_ + ": " + (path_.empty() ? "the document" : path_) + " = " +
                                quoted(object_) + " is not allowed: it must be a JSON object");
  }
}

namespace {

// The largest data file read, bytes: far above any table, scene or suite, and above the result
// of a shot at the default event budget (100,000 events of under a kilobyte each).
constexpr std::size_t kMaxInputFileBytes = std::size_t{256} << 20;
// Bytes read at a time.
constexpr std::size_t kReadBlockBytes = std::size_t{1} << 16;

}  // namespace

nlohmann::json JsonReader::parseFile(const std::string& file_path) {
  return parseStrictly(readTextFile(file_path), file_path, kValidJson);
}

std::string JsonReader::readTextFile(const std::string& file_path) {
  std::error_code error;
  if (std::filesystem::is_directory(file_path, error)) {
    throw std::invalid_argument(file_path + ": a directory is not allowed: it must be a file");
  }
  std::ifstream in(file_path, std::ios::binary);
  if (!in) {
    throw std::invalid_argument(file_path +
                                ": the file cannot be opened: it must exist and be readable");
  }
  // Read in blocks up to the limit, so that an endless input (/dev/zero, a pipe that never ends)
  // is refused instead of read until memory runs out.
  std::string text;
  std::vector<char> block(kReadBlockBytes);
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    text.append(block.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxInputFileBytes) {
      throw std::invalid_argument(file_path + ": the file is larger than " +
                                  std::to_string(kMaxInputFileBytes >> 20) +
                                  " MiB, the most a data file may be");
    }
  }
  if (in.bad()) throw std::invalid_argument(file_path + ": the file cannot be read");
  return text;
}

nlohmann::json JsonReader::parseText(const std::string& text, const std::string& source,
                                     const std::string& allowed) {
  return parseStrictly(text, source, allowed);
}

std::string JsonReader::quoted(const nlohmann::json& value) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    return physics::valueText(value.get<double>());
  }
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return cutForMessage(text, text.size());
}

std::string JsonReader::keyPath(const std::string& key) const {
  return path_.empty() ? keyText(key) : path_ + "." + keyText(key);
}

std::string JsonReader::where(const std::string& key) const {
  return source_ + ": " + keyPath(key);
}

std::string JsonReader::keyAndValue(const std::string& key) const {
  return keyPath(key) + " = " + quoted(value(key));
}

void JsonReader::reject(const std::string& key, const std::string& allowed) const {
  throw std::invalid_argument(where(key) + " = " + quoted(value(key)) +
                              " is not allowed: " + allowed);
}

void JsonReader::requireExactKeys(std::initializer_list<const char*> keys) const {
  requireKeys(keys, {});
}

void JsonReader::requireKeys(std::initializer_list<const char*> required,
                             std::initializer_list<const char*> optional) const {
  std::vector<const char*> all(required);
  all.insert(all.end(), optional.begin(), optional.end());
  std::string allowed;
  for (const char* key : all) allowed += (allowed.empty() ? "" : ", ") + std::string(key);
  for (const auto& item : object_.items()) {
    const bool known =
        std::any_of(all.begin(), all.end(), [&](const char* key) { return item.key() == key; });
    if (!known) {
      throw std::invalid_argument(where(item.key()) + " = " + quoted(item.value()) +
                                  " is not allowed: unknown key; the keys here are " + allowed);
    }
  }
  for (const char* key : required) value(key);
}

bool JsonReader::has(const std::string& key) const { return object_.contains(key); }

Eigen::Vector2d JsonReader::point(const std::string& key) const {
  const nlohmann::json& v = value(key);
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
      !std::isfinite(v[0].get<double>()) || !std::isfinite(v[1].get<double>())) {
    reject(key, "it must be an array of two finite numbers [x, y]");
  }
  return {v[0].get<double>(), v[1].get<double>()};
}

std::vector<double> JsonReader::finiteNumbers(const std::string& key, std::size_t count) const {
  const nlohmann::json& v = value(key);
  const std::string allowed = "it must be an array of " + std::to_string(count) + " finite numbers";
  if (!v.is_array() || v.size() != count) reject(key, allowed);
  std::vector<double> numbers;
  for (const nlohmann::json& item : v) {
    if (!item.is_number() || !std::isfinite(item.get<double>())) reject(key, allowed);
    numbers.push_back(item.get<double>());
  }
  return numbers;
}

std::vector<std::string> JsonReader::keys() const {
  std::vector<std::string> names;
  for (const auto& item : object_.items()) names.push_back(item.key());
  return names;
}

const nlohmann::json& JsonReader::value(const std::string& key) const {
  const auto found = object_.find(key);
  if (found == object_.end()) {
    throw std::invalid_argument(where(key) + " is missing: it is required");
  }
  return *found;
}

JsonReader JsonReader::object(const std::string& key) const {
  if (!value(key).is_object()) reject(key, "it must be a JSON object, not " + typeName(value(key)));
  return JsonReader(value(key), source_, keyPath(key));
}

std::vector<JsonReader> JsonReader::objectArray(const std::string& key) const {
  const nlohmann::json& array = value(key);
  if (!array.is_array() || array.empty()) reject(key, "it must be a non-empty array of objects");
  std::vector<JsonReader> objects;
  const std::string base = keyPath(key);
  for (std::size_t i = 0; i < array.size(); ++i) {
    objects.emplace_back(array[i], source_, base + "[" + std::to_string(i) + "]");
  }
  return objects;
}

std::string JsonReader::text(const std::string& key) const {
  const nlohmann::json& item = value(key);
  if (!item.is_string() || item.get<std::string>().empty()) {
    reject(key, "it must be a non-empty string");
  }
  return item.get<std::string>();
}

bool JsonReader::boolean(const std::string& key) const {
  if (!value(key).is_boolean()) reject(key, "it must be true or false");
  return value(key).get<bool>();
}

double JsonReader::finiteNumber(const std::string& key) const {
  const nlohmann::json& item = value(key);
  if (!item.is_number()) reject(key, "it must be a number, not " + typeName(item));
  const double number = item.get<double>();
  if (!std::isfinite(number)) reject(key, "it must be a finite number");
  return number;
}

double JsonReader::positiveNumber(const std::string& key) const {
  const double number = finiteNumber(key);
  if (!(number > 0)) reject(key, "it must be a finite number > 0");
  return number;
}

double JsonReader::nonNegativeNumber(const std::string& key) const {
  const double number = finiteNumber(key);
  if (!(number >= 0)) reject(key, "it must be a finite number >= 0");
  return number;
}

int JsonReader::integer(const std::string& key, int min, int max) const {
  const nlohmann::json& item = value(key);
  const std::string allowed =
      "it must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!item.is_number_integer()) reject(key, allowed);
  const long long number = item.get<long long>();
  if (number < min || number > max) reject(key, allowed);
  return static_cast<int>(number);
}

}  // namespace baize::engine
