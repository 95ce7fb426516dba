#pragma once
/// @file csv.hpp
/// A CSV table that grows row by row and is rewritten atomically after each row, so the file
/// on disk is always complete (header plus whole rows).

#include <string>
#include <variant>
#include <vector>

namespace sinew::io {

class CsvTable {
 public:
  using Cell = std::variant<double, long long, std::string>;

  CsvTable(std::string path, std::vector<std::string> columns);
  /// Appends a row (must have one cell per column; throws sinew::Error otherwise) and
  /// rewrites the file. Doubles are written with 17 significant digits ("%.17g");
  /// strings are quoted when they contain a comma, quote or newline.
  void add_row(const std::vector<Cell>& row);
  /// Appends without writing; call flush() to write. For tables that grow many rows per step.
  void append(const std::vector<Cell>& row);
  void flush() const;
  /// Takes the first `rows` rows of the file at path() as this table's rows (a resumed run goes
  /// on from the rows its checkpoint counted; later rows of the interrupted run are dropped).
  /// Throws InputError when the file is missing, its header is not columns(), or it has fewer rows.
  void restore(std::size_t rows);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return rows_.size(); }
  const std::string& path() const { return path_; }

 private:
  std::string header() const;
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<std::string> rows_;  // formatted lines
};

}  // namespace sinew::io
