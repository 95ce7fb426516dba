#pragma once
/// @file vtu.hpp
/// VTK XML UnstructuredGrid (.vtu) and ParaView collection (.pvd) files. Binary data is
/// base64-encoded inline (format="binary", UInt64 headers), which ParaView and meshio read.

#include <string>
#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::io {

/// One data array: rows = points (or cells), columns = components (1 scalar, 3 vector,
/// 9 tensor stored row-major per point).
struct VtuField {
  std::string name;
  Eigen::MatrixXd values;  ///< #points x components or #cells x components
};

struct VtuData {
  Positions points;                 ///< #V x 3
  Tets tets;                        ///< #T x 4 (may be empty)
  Triangles triangles;              ///< #F x 3 (may be empty); written after the tets
  std::vector<VtuField> point_fields;
  std::vector<VtuField> cell_fields;  ///< one row per cell: tets first, then triangles
  std::vector<std::pair<std::string, IndexVector>> int_cell_fields;  ///< e.g. "region"
};

/// Checks shapes (throws sinew::Error on mismatch) and writes atomically.
void write_vtu(const std::string& path, const VtuData& data);

/// A time series of .vtu files, written as a .pvd collection that ParaView opens.
class PvdSeries {
 public:
  /// `pvd_path`: the collection file; datasets are referenced relative to its directory.
  explicit PvdSeries(std::string pvd_path);
  /// Records `vtu_path` (absolute or relative to the pvd's directory) at `time` and rewrites
  /// the .pvd atomically, so the collection is valid after every step.
  void add(double time, const std::string& vtu_path);
  const std::string& path() const { return pvd_path_; }
  /// (time, file relative to the pvd's directory), sorted by time.
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }
  /// Replaces the collection by `entries` (as entries() gave them) and rewrites the .pvd: a
  /// resumed run goes on from the series its checkpoint recorded.
  void restore(std::vector<std::pair<double, std::string>> entries);

 private:
  void write() const;
  std::string pvd_path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace sinew::io
