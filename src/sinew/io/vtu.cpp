#include "sinew/io/vtu.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>
#include <string_view>
#include <system_error>

#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/io/base64.hpp"
#include "sinew/io/xml_escape.hpp"

namespace sinew::io {

namespace fs = std::filesystem;

namespace {

constexpr std::uint8_t kVtkTriangle = 5;
constexpr std::uint8_t kVtkTetra = 10;

/// Shortest decimal text that reads back to exactly `value`.
std::string format_double(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

/// Raw little-endian bytes of a data array, built value by value.
class ByteBuffer {
 public:
  explicit ByteBuffer(std::size_t expected_values, std::size_t bytes_per_value) {
    bytes_.reserve(expected_values * bytes_per_value);
  }

  template <typename T>
  void push(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) {
      std::reverse(raw, raw + sizeof(T));
    }
    bytes_.append(raw, sizeof(T));
  }

  void append(const ByteBuffer& other) { bytes_ += other.bytes_; }

  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

/// Writes one `<DataArray>` element whose content is base64(UInt64 byte count + data).
void append_data_array(std::string& xml, std::string_view indent, std::string_view type,
                       std::string_view name, Eigen::Index components, const ByteBuffer& data) {
  xml += indent;
  xml += "<DataArray type=\"";
  xml += type;
  xml += "\" Name=\"";
  xml += xml_escape(name);
  xml += "\" NumberOfComponents=\"";
  xml += std::to_string(components);
  xml += "\" format=\"binary\">\n";
  xml += indent;
  xml += "  ";
  ByteBuffer payload(1, 8 + data.bytes().size());
  payload.push(static_cast<std::uint64_t>(data.bytes().size()));
  payload.append(data);
  append_base64(xml, payload.bytes().data(), payload.bytes().size());
  xml += "\n";
  xml += indent;
  xml += "</DataArray>\n";
}

/// Row-major Float64 bytes of `values` (#rows x #columns).
ByteBuffer float64_rows(const Eigen::MatrixXd& values) {
  ByteBuffer buffer(static_cast<std::size_t>(values.size()), 8);
  for (Eigen::Index row = 0; row < values.rows(); ++row) {
    for (Eigen::Index column = 0; column < values.cols(); ++column) {
      buffer.push(values(row, column));
    }
  }
  return buffer;
}

/// Checks a VtuData before anything is written; every message names the file and the field.
class VtuValidator {
 public:
  VtuValidator(const std::string& path, const VtuData& data) : path_(path), data_(data) {}

  void check() const {
    check_points();
    check_elements(data_.tets, "tetrahedron");
    check_elements(data_.triangles, "triangle");
    const Eigen::Index num_points = data_.points.rows();
    const Eigen::Index num_cells = data_.tets.rows() + data_.triangles.rows();

    std::set<std::string> point_names;
    for (const VtuField& field : data_.point_fields) {
      check_name(field.name, "point field", "point data", point_names);
      check_rows(field.name, "point field", field.values.rows(), num_points, "one per point");
      check_columns(field, "point field");
    }
    std::set<std::string> cell_names;
    for (const VtuField& field : data_.cell_fields) {
      check_name(field.name, "cell field", "cell data", cell_names);
      check_rows(field.name, "cell field", field.values.rows(), num_cells, kCellRowMeaning);
      check_columns(field, "cell field");
    }
    for (const auto& [name, values] : data_.int_cell_fields) {
      check_name(name, "integer cell field", "cell data", cell_names);
      check_rows(name, "integer cell field", values.rows(), num_cells, kCellRowMeaning);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error("cannot write VTU file '" + path_ + "': " + message);
  }

  void check_points() const {
    for (Eigen::Index node = 0; node < data_.points.rows(); ++node) {
      if (!data_.points.row(node).allFinite()) {
        fail("point " + std::to_string(node) + " has a non-finite coordinate (" +
             format_double(data_.points(node, 0)) + ", " + format_double(data_.points(node, 1)) +
             ", " + format_double(data_.points(node, 2)) + ")");
      }
    }
  }

  template <typename Elements>
  void check_elements(const Elements& elements, const std::string& kind) const {
    const Eigen::Index num_points = data_.points.rows();
    for (Eigen::Index element = 0; element < elements.rows(); ++element) {
      for (Eigen::Index corner = 0; corner < elements.cols(); ++corner) {
        const Index node = elements(element, corner);
        if (node < 0 || node >= num_points) {
          fail(kind + " " + std::to_string(element) + " refers to node " + std::to_string(node) +
               ", outside [0, " + std::to_string(num_points) + ")");
        }
      }
    }
  }

  void check_name(const std::string& name, const std::string& kind, const std::string& group,
                  std::set<std::string>& names_in_group) const {
    if (name.empty()) fail("a " + kind + " has an empty name");
    if (!names_in_group.insert(name).second) {
      fail("two arrays in the " + group + " are named '" + name + "'");
    }
  }

  void check_rows(const std::string& name, const std::string& kind, Eigen::Index rows,
                  Eigen::Index expected_rows, const std::string& row_meaning) const {
    if (rows != expected_rows) {
      fail(kind + " '" + name + "' has " + std::to_string(rows) + " rows, expected " +
           std::to_string(expected_rows) + " (" + row_meaning + ")");
    }
  }

  void check_columns(const VtuField& field, const std::string& kind) const {
    if (field.values.cols() < 1) fail(kind + " '" + field.name + "' has no columns (components)");
  }

  static constexpr const char* kCellRowMeaning = "one per cell: tets first, then triangles";

  const std::string& path_;
  const VtuData& data_;
};

}  // namespace

void write_vtu(const std::string& path, const VtuData& data) {
  VtuValidator(path, data).check();

  const Eigen::Index num_points = data.points.rows();
  const Eigen::Index num_tets = data.tets.rows();
  const Eigen::Index num_triangles = data.triangles.rows();
  const Eigen::Index num_cells = num_tets + num_triangles;

  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n";
  xml += "  <UnstructuredGrid>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(num_points) + "\" NumberOfCells=\"" +
         std::to_string(num_cells) + "\">\n";

  xml += "      <Points>\n";
  {
    ByteBuffer points(static_cast<std::size_t>(num_points) * 3, 8);
    for (Eigen::Index node = 0; node < num_points; ++node) {
      for (int axis = 0; axis < 3; ++axis) points.push(data.points(node, axis));
    }
    append_data_array(xml, "        ", "Float64", "Points", 3, points);
  }
  xml += "      </Points>\n";

  xml += "      <Cells>\n";
  {
    const auto num_corners = static_cast<std::size_t>(4 * num_tets + 3 * num_triangles);
    ByteBuffer connectivity(num_corners, 8);
    ByteBuffer offsets(static_cast<std::size_t>(num_cells), 8);
    ByteBuffer types(static_cast<std::size_t>(num_cells), 1);
    std::int64_t offset = 0;
    for (Eigen::Index tet = 0; tet < num_tets; ++tet) {
      for (int corner = 0; corner < 4; ++corner) {
        connectivity.push(static_cast<std::int64_t>(data.tets(tet, corner)));
      }
      offset += 4;
      offsets.push(offset);
      types.push(kVtkTetra);
    }
    for (Eigen::Index triangle = 0; triangle < num_triangles; ++triangle) {
      for (int corner = 0; corner < 3; ++corner) {
        connectivity.push(static_cast<std::int64_t>(data.triangles(triangle, corner)));
      }
      offset += 3;
      offsets.push(offset);
      types.push(kVtkTriangle);
    }
    append_data_array(xml, "        ", "Int64", "connectivity", 1, connectivity);
    append_data_array(xml, "        ", "Int64", "offsets", 1, offsets);
    append_data_array(xml, "        ", "UInt8", "types", 1, types);
  }
  xml += "      </Cells>\n";

  xml += "      <PointData>\n";
  for (const VtuField& field : data.point_fields) {
    append_data_array(xml, "        ", "Float64", field.name, field.values.cols(),
                      float64_rows(field.values));
  }
  xml += "      </PointData>\n";

  xml += "      <CellData>\n";
  for (const VtuField& field : data.cell_fields) {
    append_data_array(xml, "        ", "Float64", field.name, field.values.cols(),
                      float64_rows(field.values));
  }
  for (const auto& [name, values] : data.int_cell_fields) {
    ByteBuffer ints(static_cast<std::size_t>(values.rows()), 4);
    for (Eigen::Index cell = 0; cell < values.rows(); ++cell) {
      ints.push(static_cast<std::int32_t>(values(cell)));
    }
    append_data_array(xml, "        ", "Int32", name, 1, ints);
  }
  xml += "      </CellData>\n";

  xml += "    </Piece>\n";
  xml += "  </UnstructuredGrid>\n";
  xml += "</VTKFile>\n";

  write_file_atomically(path, xml);
}

PvdSeries::PvdSeries(std::string pvd_path) : pvd_path_(std::move(pvd_path)) {
  if (pvd_path_.empty()) throw Error("PvdSeries: the .pvd path is empty");
}

void PvdSeries::add(double time, const std::string& vtu_path) {
  if (!std::isfinite(time)) {
    throw Error("cannot add '" + vtu_path + "' to the collection '" + pvd_path_ +
                "': the time " + format_double(time) + " is not finite");
  }
  if (vtu_path.empty()) {
    throw Error("cannot add a dataset to the collection '" + pvd_path_ + "': empty file path");
  }

  fs::path dataset(vtu_path);
  if (dataset.is_absolute()) {
    std::error_code ec;
    const fs::path pvd_directory =
        fs::absolute(fs::path(pvd_path_), ec).parent_path().lexically_normal();
    if (!ec) {
      const fs::path relative = dataset.lexically_normal().lexically_relative(pvd_directory);
      if (!relative.empty()) dataset = relative;
    }
  } else {
    dataset = dataset.lexically_normal();
  }

  // Keep the collection sorted by time; equal times keep their order of addition.
  const auto position =
      std::upper_bound(entries_.begin(), entries_.end(), time,
                       [](double t, const std::pair<double, std::string>& entry) {
                         return t < entry.first;
                       });
  const auto inserted = entries_.insert(position, {time, dataset.generic_string()});
  try {
    write();
  } catch (...) {
    entries_.erase(inserted);  // the collection on disk and in memory stay the same
    throw;
  }
}

void PvdSeries::restore(std::vector<std::pair<double, std::string>> entries) {
  entries_ = std::move(entries);
  write();
}

void PvdSeries::write() const {
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  xml += "  <Collection>\n";
  for (const auto& [entry_time, file] : entries_) {
    xml += "    <DataSet timestep=\"" + format_double(entry_time) + "\" group=\"\" part=\"0\" file=\"" +
           xml_escape(file) + "\"/>\n";
  }
  xml += "  </Collection>\n";
  xml += "</VTKFile>\n";
  write_file_atomically(pvd_path_, xml);
}

}  // namespace sinew::io
