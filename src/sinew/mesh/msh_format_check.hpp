#pragma once
/// @file msh_format_check.hpp
/// Checks a mesh file before Gmsh sees it (see docs/input-safety.md).
///
/// Gmsh's file loader picks a reader from the file's extension and its first line: anything it
/// does not recognise as a mesh is parsed as a Gmsh script (.geo), whose `System "..."`
/// statements run shell commands. Gmsh's MSH readers also allocate from the counts written in
/// section headers before reading the data they announce. So a mesh file reaches Gmsh only
/// after check_msh_file() has read it and found a genuine MSH file whose counts fit in it.

#include <cstdint>
#include <string>

namespace sinew::mesh {

/// Larger mesh files are refused (2 GiB).
inline constexpr std::uintmax_t kMaxMshFileBytes = std::uintmax_t{2} << 30;

/// The `$MeshFormat` header of an MSH file.
struct MshFileFormat {
  double version = 0;   ///< 2.2, 4.0 or 4.1
  bool binary = false;  ///< file-type 1
};

/// Throws InputError naming `path` unless it is a regular file (not a FIFO, device or
/// directory) named *.msh, at most kMaxMshFileBytes long. Only looks at the file's status.
void check_msh_path(const std::string& path);

/// Reads the file at `path` and throws InputError naming `shown_path` unless its first line is
/// `$MeshFormat` followed by a "<version> <file-type> <data-size>" line with version 2.2, 4.0
/// or 4.1, file-type 0 (ASCII) or 1 (binary; not for 4.0) and data-size 8, closed by
/// `$EndMeshFormat`; and its `$Nodes` and `$Elements` sections are present (nodes first) and
/// closed by `$EndNodes` / `$EndElements`, every section being closed. Every count of those
/// sections (and of `$Entities`, `$PhysicalNames`, `$InterpolationScheme` and the data
/// sections) must fit in the bytes that follow it, node tags must be unique, elements must be
/// of a type 1-19 and refer to defined node tags, `$NodeData` values to defined nodes and
/// `$ElementData` / `$ElementNodeData` values to defined elements.
MshFileFormat check_msh_content(const std::string& path, const std::string& shown_path);

/// check_msh_path(path), then check_msh_content(path, path).
MshFileFormat check_msh_file(const std::string& path);

}  // namespace sinew::mesh
