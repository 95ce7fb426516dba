#pragma once
/// @file triangle_mirror.hpp
/// Copies a symmetric matrix's lower triangle onto its upper one, through a map of twin entries
/// built once per sparsity pattern.
///
/// Why: CHOLMOD permutes an upper-stored matrix for its supernodal factorization with one
/// transpose, a lower-stored one with two (cholmod_factorize_p). The Newton matrix K is stored
/// whole, and its two triangles differ in the last bits (each is summed in its own order). Handing
/// CHOLMOD K with its lower triangle mirrored onto the upper one, as an upper-stored matrix, saves
/// the second transpose and factorizes exactly the numbers the lower-stored K gave it
/// (docs/solver.md, "The factorization's settings, machine code and the pattern's binding").

#include <vector>

#include "sinew/core/sparse_matrix.hpp"

namespace sinew::solver {

/// For every entry above the diagonal of a compressed, structurally symmetric matrix, the index
/// of that entry and of its twin below the diagonal in the matrix's value array.
struct TriangleMirror {
  std::vector<int> upper;  ///< value indices of the entries (i, j), i < j, column by column
  std::vector<int> lower;  ///< value indices of their twins (j, i), in the same order
  int rows = 0;            ///< the pattern's size and number of stored entries, to check a matrix
  int stored = 0;          ///< against the map before it is applied
};

/// The twins of `pattern` (square, compressed, rows sorted in each column, as Eigen keeps them).
/// Throws sinew::Error when an entry has no twin (the pattern is not symmetric).
TriangleMirror triangle_mirror(const SparseMatrix& pattern);

/// True when `matrix` has the size and the number of stored entries the map was built for (a
/// necessary condition for the same pattern; the callers change the pattern only together with
/// a new analysis, when the map is rebuilt).
bool fits(const TriangleMirror& mirror, const SparseMatrix& matrix);

/// Overwrites each entry above the diagonal of `matrix` with its twin below it: afterwards
/// `matrix` is symmetric to the last bit and its lower triangle is unchanged.
/// Requires fits(mirror, matrix).
void mirror_lower_to_upper(const TriangleMirror& mirror, SparseMatrix& matrix);

}  // namespace sinew::solver
