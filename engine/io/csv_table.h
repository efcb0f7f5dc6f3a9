// A CSV file as the tools write it (a header row, then rows of plain comma-separated fields, no
// quoting), read back for charts. Errors name the file, the line and the column.
#pragma once

#include <string>
#include <vector>

namespace baize::engine {

class CsvTable {
 public:
  // Throws std::invalid_argument when the file cannot be read, has no header, or a row has a
  // different number of fields than the header.
  static CsvTable read(const std::string& path);

  const std::string& path() const { return path_; }
  size_t rowCount() const { return rows_.size(); }
  const std::vector<std::string>& header() const { return header_; }
  // Throws std::invalid_argument naming the file and the columns it has when `name` is missing.
  size_t column(const std::string& name) const;
  // Whether the header has a column `name` (for optional columns).
  bool hasColumn(const std::string& name) const;
  const std::string& text(size_t row, size_t column) const { return rows_[row][column]; }
  // The field as a finite number; throws std::invalid_argument naming file, line and column.
  double number(size_t row, size_t column) const;
  // The line of the file that row `row` came from, for messages.
  int lineNumber(size_t row) const { return line_numbers_[row]; }

 private:
  std::string path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<int> line_numbers_;  // of each row in the file, for messages
};

}  // namespace baize::engine
