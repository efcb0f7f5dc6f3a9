#include "engine/json_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "physics/value_text.h"

namespace baize::engine {
namespace {

// Values as JSON text (numbers in their shortest exact form); NaN and infinities, which JSON
// cannot hold, as "nan" and "inf".
std::string jsonText(const nlohmann::json& value) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    return physics::valueText(value.get<double>());
  }
  return value.dump();
}

std::string typeName(const nlohmann::json& value) { return value.type_name(); }

}  // namespace

JsonReader::JsonReader(const nlohmann::json& object, std::string source, std::string path)
    : object_(object), source_(std::move(source)), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw std::invalid_argument(source_ + ": " + (path_.empty() ? "the document" : path_) + " = " +
                                jsonText(object_) + " is not allowed: it must be a JSON object");
  }
}

nlohmann::json JsonReader::parseFile(const std::string& file_path) {
  std::ifstream in(file_path);
  if (!in) {
    throw std::invalid_argument(file_path +
                                ": the file cannot be opened: it must exist and be readable");
  }
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    // Parse errors and numbers too large for a double (1e999) alike.
    throw std::invalid_argument(file_path + ": not valid JSON (" + error.what() +
                                ") is not allowed: it must be JSON with finite numbers");
  }
}

std::string JsonReader::where(const std::string& key) const {
  return source_ + ": " + (path_.empty() ? key : path_ + "." + key);
}

void JsonReader::reject(const std::string& key, const std::string& allowed) const {
  throw std::invalid_argument(where(key) + " = " + jsonText(value(key)) +
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
      throw std::invalid_argument(where(item.key()) + " = " + jsonText(item.value()) +
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
  return JsonReader(value(key), source_, path_.empty() ? key : path_ + "." + key);
}

std::vector<JsonReader> JsonReader::objectArray(const std::string& key) const {
  const nlohmann::json& array = value(key);
  if (!array.is_array() || array.empty()) reject(key, "it must be a non-empty array of objects");
  std::vector<JsonReader> objects;
  const std::string base = path_.empty() ? key : path_ + "." + key;
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
