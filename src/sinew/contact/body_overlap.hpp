#pragma once
/// @file body_overlap.hpp
/// Where bodies overlap in one configuration (typically the start): per pair of bodies, the
/// deepest penetration and its place, kept apart for the (triangle, tet) pairs that contact
/// takes and those it leaves out because neither side can move (ContactGeometry::node_immovable;
/// docs/contact.md, "Parts that overlap at the start").

#include <vector>

#include "sinew/contact/contact_geometry.hpp"

namespace sinew::contact {

/// One overlap of two bodies (or of one body with itself).
struct BodyOverlap {
  Index body_a = 0;        ///< body_a <= body_b; equal for self-contact
  Index body_b = 0;
  bool immovable = false;  ///< the pairs counted here are all immovable (left out of contact)
  Index pairs = 0;         ///< overlapping (triangle, tet) pairs
  double max_depth = 0;    ///< largest interpolated depth on the pairs' polygons (L), > 0
  Vector3 place = Vector3::Zero();  ///< centroid of the triangle of the deepest pair at x (L)
};

/// The overlaps at x (#V x 3, L) of the pairs of `geometry` with a penalty > 0 and a depth
/// larger than `min_depth` (L): at most one entry per (body pair, immovable), deepest first.
/// Immovable pairs are found although contact leaves them out.
std::vector<BodyOverlap> body_overlaps(const ContactGeometry& geometry, const Positions& x, ContactMethod method,
                                       double min_depth);

}  // namespace sinew::contact
