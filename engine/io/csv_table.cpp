#include "engine/io/csv_table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace baize::engine {
namespace {

std::vector<std::string> fieldsOf(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // a trailing empty field
  return fields;
}

}  // namespace

CsvTable CsvTable::read(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(path + ": a directory is not allowed: it must be a CSV file");
  }
  std::ifstream in(path);
  if (!in) {
    throw std::invalid_argument(path +
                                ": the file cannot be opened: it must exist and be readable");
  }
  CsvTable table;
  table.path_ = path;
  std::string line;
  // Lines may end in CRLF (a file from Windows): the CR is not part of the last field.
  const auto next = [&](std::string& text) {
    if (!std::getline(in, text)) return false;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (const auto nul = text.find('\0'); nul != std::string::npos) {
      throw std::invalid_argument(path + ": a NUL byte is not allowed: it must be a text file");
    }
    return true;
  };
  if (!next(line) || line.empty()) {
    throw std::invalid_argument(path + ": no header row: the file must start with column names");
  }
  table.header_ = fieldsOf(line);
  for (int line_number = 2; next(line); ++line_number) {
    if (line.empty()) continue;
    std::vector<std::string> fields = fieldsOf(line);
    if (fields.size() != table.header_.size()) {
      throw std::invalid_argument(path + " line " + std::to_string(line_number) + ": " +
                                  std::to_string(fields.size()) + " fields, but the header has " +
                                  std::to_string(table.header_.size()));
    }
    table.rows_.push_back(std::move(fields));
    table.line_numbers_.push_back(line_number);
  }
  return table;
}

bool CsvTable::hasColumn(const std::string& name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

size_t CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return i;
  }
  std::string columns;
  for (const std::string& h : header_) columns += (columns.empty() ? "" : ",") + h;
  throw std::invalid_argument(path_ + ": no column '" + name + "' (the header is " + columns + ")");
}

double CsvTable::number(size_t row, size_t column) const {
  const std::string& field = rows_[row][column];
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  const std::string where = path_ + " line " + std::to_string(line_numbers_[row]) + ", column " +
                            header_[column] + " = '" + field;
  if (field.empty() || *end != '\0') {
    throw std::invalid_argument(where + "' is not allowed: it must be a number");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument(where + "' is not allowed: it must be a finite number");
  }
  return value;
}

}  // namespace baize::engine
