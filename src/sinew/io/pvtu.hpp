#pragma once
/// @file pvtu.hpp
/// Parallel VTK XML UnstructuredGrid files (.pvtu): a dataset split into pieces, one .vtu per
/// MPI rank written by that rank, and a small .pvtu that lists them and declares their arrays.
/// ParaView opens a .pvtu (and a .pvd collection of them) as one dataset (docs/mpi.md, "Output").

#include <string>
#include <vector>

#include "sinew/io/vtu.hpp"

namespace sinew::io {

/// The part of `whole` made of its tets `tets` and triangles `triangles` (indices into whole's
/// tets and triangles, in the order the piece lists them): the points those cells use, in
/// increasing order of their index in `whole`, with the point fields restricted to them and the
/// cell fields to those cells (tets first, then triangles). A point shared by two pieces is in
/// both. Throws sinew::Error when an index is not a cell of `whole` or a cell refers to a point
/// `whole` does not have.
VtuData vtu_piece(const VtuData& whole, const std::vector<Index>& tets, const std::vector<Index>& triangles);

/// Writes the .pvtu at `path` listing `pieces` (file names relative to the .pvtu's directory,
/// in order) and declaring the arrays of `layout` (a piece or the whole dataset: only the names,
/// types and numbers of components of its fields are used). Written atomically (a no-op where
/// files_written() is false). Throws sinew::Error for no piece or an empty piece name.
void write_pvtu(const std::string& path, const VtuData& layout, const std::vector<std::string>& pieces);

}  // namespace sinew::io
