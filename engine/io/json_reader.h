// Strict reading of JSON data files: every error names the file, the key path and the value, and
// says what is allowed. One reader serves the table and ball-set loaders.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace baize::engine {

// A view of one JSON object inside a document, remembering where it came from (the file name and
// the key path, such as "corner_pocket" or "balls[3]") so that errors can say so.
class JsonReader {
 public:
  // `source` names the document in messages (usually its file path).
  JsonReader(const nlohmann::json& object, std::string source, std::string path = "");

  // What parseFile says a file must be when it is not valid JSON.
  static constexpr const char* kValidJson = "it must be JSON with finite numbers";

  // Parses the file. Throws std::invalid_argument when it cannot be opened, is not valid JSON (the
  // message holds the parser's line and column) or has a key twice in one object (the message names
  // the key path): nlohmann::json alone would keep the last value silently.
  // Refuses a NUL byte and nesting deeper than 64 levels.
  static nlohmann::json parseFile(const std::string& file_path);
  // A file's whole content; throws std::invalid_argument naming the file when it is a directory or
  // cannot be opened or read.
  static std::string readTextFile(const std::string& file_path);
  // Parses JSON text as parseFile parses a file; `source` names it in messages and `allowed` says
  // what the text must be when it is not valid JSON.
  static nlohmann::json parseText(const std::string& text, const std::string& source,
                                  const std::string& allowed = kValidJson);

  // Throws unless the object has exactly these keys: an unknown key or a missing one is named.
  void requireExactKeys(std::initializer_list<const char*> keys) const;
  // Throws unless every key is among `required` and `optional` and every required key is present.
  void requireKeys(std::initializer_list<const char*> required,
                   std::initializer_list<const char*> optional) const;
  bool has(const std::string& key) const;
  // A JSON array of two finite numbers, such as a position [x, y].
  Eigen::Vector2d point(const std::string& key) const;
  // A JSON array of exactly `count` finite numbers.
  std::vector<double> finiteNumbers(const std::string& key, std::size_t count) const;
  // The object's keys (sorted: nlohmann::json keeps objects ordered by key).
  std::vector<std::string> keys() const;

  JsonReader object(const std::string& key) const;
  std::vector<JsonReader> objectArray(const std::string& key) const;  // a non-empty array
  std::string text(const std::string& key) const;                     // a non-empty string
  bool boolean(const std::string& key) const;
  double finiteNumber(const std::string& key) const;
  double positiveNumber(const std::string& key) const;          // finite and > 0
  double nonNegativeNumber(const std::string& key) const;       // finite and >= 0
  int integer(const std::string& key, int min, int max) const;  // an integer in [min, max]

  std::string keyPath(const std::string& key) const;  // "path.key", escaped and cut

  // "source: path.key" for messages about a value that passed its own check but not a relation.
  std::string where(const std::string& key) const;
  // "path.key = <the value as written>", for naming a second value in a message about the first.
  std::string keyAndValue(const std::string& key) const;

  // A value as messages quote it: JSON text (NaN and infinities, which JSON cannot hold, as "nan"
  // and "inf"), bytes that are not UTF-8 replaced, cut after 200 characters saying how long it was.
  static std::string quoted(const nlohmann::json& value);

  // The object itself and where it came from, to keep it for reading again later.
  const nlohmann::json& json() const { return object_; }
  const std::string& source() const { return source_; }
  const std::string& path() const { return path_; }

  // Throws std::invalid_argument("<source>: <path.key> = <value> is not allowed: <allowed>").
  [[noreturn]] void reject(const std::string& key, const std::string& allowed) const;

 private:
  const nlohmann::json& value(const std::string& key) const;  // throws when the key is missing

  const nlohmann::json& object_;
  std::string source_;
  std::string path_;
};

}  // namespace baize::engine
