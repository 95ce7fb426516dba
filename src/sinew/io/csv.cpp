#include "sinew/io/csv.hpp"

#include <cstdio>
#include <fstream>
#include <set>
#include <string_view>

#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"

namespace sinew::io {

namespace {

/// `text` as one CSV field: quoted (with quotes doubled, RFC 4180) when it contains a
/// comma, a quote or a line break, as is otherwise.
std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

struct CellFormatter {
  std::string operator()(double value) const {
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), "%.17g", value);
    return buffer;
  }
  std::string operator()(long long value) const { return std::to_string(value); }
  std::string operator()(const std::string& value) const { return csv_field(value); }
};

}  // namespace

CsvTable::CsvTable(std::string path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) throw Error("CSV table '" + path_ + "' has no columns");
  std::set<std::string_view> seen;
  for (const std::string& column : columns_) {
    if (!seen.insert(column).second) {
      throw Error("CSV table '" + path_ + "' has two columns named '" + column + "'");
    }
  }
}

void CsvTable::add_row(const std::vector<Cell>& row) {
  append(row);
  flush();
}

void CsvTable::append(const std::vector<Cell>& row) {
  if (row.size() != columns_.size()) {
    throw Error("CSV table '" + path_ + "': row " + std::to_string(rows_.size() + 1) + " has " +
                std::to_string(row.size()) + " cells, expected " + std::to_string(columns_.size()) +
                " (one per column)");
  }
  std::string line;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i > 0) line += ',';
    line += std::visit(CellFormatter{}, row[i]);
  }
  rows_.push_back(std::move(line));
}

std::string CsvTable::header() const {
  std::string content;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) content += ',';
    content += csv_field(columns_[i]);
  }
  return content;
}

void CsvTable::restore(std::size_t rows) {
  std::ifstream in(path_);
  if (!in) throw InputError("cannot resume: '" + path_ + "' is missing or unreadable");
  std::string line;
  if (!std::getline(in, line) || line != header())
    throw InputError("cannot resume: '" + path_ + "' does not have the columns this scene writes");
  std::vector<std::string> kept;
  while (kept.size() < rows && std::getline(in, line)) kept.push_back(line);
  if (kept.size() < rows)
    throw InputError("cannot resume: '" + path_ + "' has " + std::to_string(kept.size()) +
                     " rows, the checkpoint counted " + std::to_string(rows));
  rows_ = std::move(kept);
}

void CsvTable::flush() const {
  std::string content = header();
  content += '\n';
  for (const std::string& line : rows_) {
    content += line;
    content += '\n';
  }
  write_file_atomically(path_, content);
}

}  // namespace sinew::io
