#include "sinew/io/pvtu.hpp"

#include <algorithm>

#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/io/xml_escape.hpp"

namespace sinew::io {

namespace {

/// Rows `rows` of `values`, in order.
template <class Matrix>
Matrix take_rows(const Matrix& values, const std::vector<Index>& rows) {
  Matrix out(static_cast<Eigen::Index>(rows.size()), values.cols());
  for (std::size_t k = 0; k < rows.size(); ++k) out.row(static_cast<Eigen::Index>(k)) = values.row(rows[k]);
  return out;
}

/// One <PDataArray> declaration (the array's data is in the pieces).
void declare(std::string& xml, const char* type, const std::string& name, Eigen::Index components) {
  xml += "      <PDataArray type=\"";
  xml += type;
  xml += "\" Name=\"" + xml_escape(name) + "\" NumberOfComponents=\"" + std::to_string(components) + "\"/>\n";
}

}  // namespace

VtuData vtu_piece(const VtuData& whole, const std::vector<Index>& tets, const std::vector<Index>& triangles) {
  const Index num_tets = whole.tets.rows();
  const Index num_triangles = whole.triangles.rows();
  for (const Index t : tets)
    if (t < 0 || t >= num_tets)
      throw Error("a VTU piece: tet " + std::to_string(t) + " of " + std::to_string(num_tets) + " asked for");
  for (const Index f : triangles)
    if (f < 0 || f >= num_triangles)
      throw Error("a VTU piece: triangle " + std::to_string(f) + " of " + std::to_string(num_triangles) + " asked for");

  // The points the cells use, numbered in the order of their index in `whole`.
  const Index num_points = whole.points.rows();
  std::vector<Index> local(static_cast<std::size_t>(num_points), -1);
  auto mark = [&](Index node) {
    if (node < 0 || node >= num_points)
      throw Error("a VTU piece: a cell refers to point " + std::to_string(node) + " of " + std::to_string(num_points));
    local[static_cast<std::size_t>(node)] = 0;
  };
  for (const Index t : tets)
    for (int c = 0; c < 4; ++c) mark(whole.tets(t, c));
  for (const Index f : triangles)
    for (int c = 0; c < 3; ++c) mark(whole.triangles(f, c));
  std::vector<Index> points;
  for (Index v = 0; v < num_points; ++v)
    if (local[static_cast<std::size_t>(v)] == 0) {
      local[static_cast<std::size_t>(v)] = static_cast<Index>(points.size());
      points.push_back(v);
    }

  VtuData piece;
  piece.points = take_rows(whole.points, points);
  piece.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t k = 0; k < tets.size(); ++k)
    for (int c = 0; c < 4; ++c)
      piece.tets(static_cast<Eigen::Index>(k), c) = local[static_cast<std::size_t>(whole.tets(tets[k], c))];
  piece.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (int c = 0; c < 3; ++c)
      piece.triangles(static_cast<Eigen::Index>(k), c) = local[static_cast<std::size_t>(whole.triangles(triangles[k], c))];
  for (const VtuField& field : whole.point_fields) piece.point_fields.push_back({field.name, take_rows(field.values, points)});

  // Cell rows: the tets, then the triangles (after all of whole's tets).
  std::vector<Index> cells(tets.begin(), tets.end());
  cells.reserve(tets.size() + triangles.size());
  for (const Index f : triangles) cells.push_back(num_tets + f);
  const Index num_cells = num_tets + num_triangles;
  auto check_cell_rows = [&](const std::string& name, Eigen::Index rows) {
    if (rows != num_cells)
      throw Error("a VTU piece: cell field '" + name + "' has " + std::to_string(rows) + " rows for " +
                  std::to_string(num_cells) + " cells");
  };
  for (const VtuField& field : whole.cell_fields) {
    check_cell_rows(field.name, field.values.rows());
    piece.cell_fields.push_back({field.name, take_rows(field.values, cells)});
  }
  for (const auto& [name, values] : whole.int_cell_fields) {
    check_cell_rows(name, values.rows());
    piece.int_cell_fields.emplace_back(name, take_rows(values, cells));
  }
  return piece;
}

void write_pvtu(const std::string& path, const VtuData& layout, const std::vector<std::string>& pieces) {
  if (pieces.empty()) throw Error("cannot write the parallel VTU file '" + path + "': no pieces");
  for (const std::string& piece : pieces)
    if (piece.empty()) throw Error("cannot write the parallel VTU file '" + path + "': a piece has no file name");
  // The types are those write_vtu gives the arrays (vtu.cpp).
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  xml += "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  xml += "    <PPoints>\n";
  xml += "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n";
  xml += "    </PPoints>\n";
  xml += "    <PPointData>\n";
  for (const VtuField& field : layout.point_fields) declare(xml, "Float64", field.name, field.values.cols());
  xml += "    </PPointData>\n";
  xml += "    <PCellData>\n";
  for (const VtuField& field : layout.cell_fields) declare(xml, "Float64", field.name, field.values.cols());
  for (const auto& [name, values] : layout.int_cell_fields) declare(xml, "Int32", name, 1);
  xml += "    </PCellData>\n";
  for (const std::string& piece : pieces) xml += "    <Piece Source=\"" + xml_escape(piece) + "\"/>\n";
  xml += "  </PUnstructuredGrid>\n";
  xml += "</VTKFile>\n";
  write_file_atomically(path, xml);
}

}  // namespace sinew::io
