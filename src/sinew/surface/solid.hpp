#pragma once
/// @file solid.hpp
/// Solids bounded by closed surfaces, combined as point sets: the regions of a mesh made from
/// scanned surfaces (docs/surface-input.md, solids). A solid is a test "is x inside?", so crops,
/// offsets and booleans are exact by construction; the mesher finds the boundary.

#include <map>
#include <string>
#include <vector>

#include "sinew/core/enum_names.hpp"
#include "sinew/core/types.hpp"
#include "sinew/surface/closed_surface.hpp"

namespace sinew::surface {

/// A solid, in scene units.
struct Solid {
  enum class Kind { Surface, Offset, Box, Capsule, Ellipsoid, HalfSpace, Union, Difference, Intersection };
  Kind kind = Kind::Surface;
  /// Surface: one name of a closed surface (a key of the SurfaceLibrary). Offset: the surfaces
  /// whose union is offset.
  std::vector<std::string> surfaces;
  /// Offset: the points within this distance of the union of `surfaces` or inside it (> 0 grows:
  /// a hull around parts), or inside it and deeper than -distance (< 0 shrinks). Length.
  double distance = 0;
  Vector3 min = Vector3::Zero(), max = Vector3::Zero();  ///< Box corners
  /// Capsule: the ends of its axis segment. Ellipsoid: `a` is the centre.
  Vector3 a = Vector3::Zero(), b = Vector3::Zero();
  double radius = 0;  ///< Capsule radius (length)
  /// Ellipsoid: semi-axis lengths along `axis_u`, `axis_v` (made orthogonal to axis_u) and
  /// axis_u x axis_v.
  Vector3 semi_axes = Vector3::Ones();
  Vector3 axis_u = Vector3::UnitX(), axis_v = Vector3::UnitY();
  /// HalfSpace: the points x with (x - point) . normal <= 0 (normal points out of the solid).
  Vector3 point = Vector3::Zero(), normal = Vector3::UnitZ();
  /// Union: in any child. Difference: in children[0] and in no other. Intersection: in all.
  std::vector<Solid> children;
};

/// Scene names of Solid::Kind (the keys of a solid object).
inline constexpr NameTable<Solid::Kind, 9> kSolidKindNames{{
    {Solid::Kind::Surface, "surface"},
    {Solid::Kind::Offset, "offset"},
    {Solid::Kind::Box, "box"},
    {Solid::Kind::Capsule, "capsule"},
    {Solid::Kind::Ellipsoid, "ellipsoid"},
    {Solid::Kind::HalfSpace, "half_space"},
    {Solid::Kind::Union, "union"},
    {Solid::Kind::Difference, "difference"},
    {Solid::Kind::Intersection, "intersection"},
}};
constexpr const auto& enum_names(Solid::Kind) { return kSolidKindNames; }

/// The closed surfaces solids refer to, by name.
using SurfaceLibrary = std::map<std::string, ClosedSurface>;

/// Throws InputError (naming `what`) when the solid names a surface the library lacks, or has a
/// zero normal, radius, semi-axis or axis, or a boolean without children.
void check_solid(const Solid& solid, const SurfaceLibrary& library, const std::string& what);

/// True when `point` is in the solid (on its boundary counts as in).
bool solid_contains(const Solid& solid, const SurfaceLibrary& library, const Vector3& point);

/// Bounds that contain the solid (possibly larger; unbounded for a lone half-space).
Bounds solid_bounds(const Solid& solid, const SurfaceLibrary& library);

/// The distance from x to the segment a-b (length; a = b: to the point a).
double segment_distance(const Vector3& a, const Vector3& b, const Vector3& x);

/// The distance from `point` to the union of the named surfaces, negative inside (length).
double union_signed_distance(const std::vector<std::string>& surfaces, const SurfaceLibrary& library,
                             const Vector3& point);

}  // namespace sinew::surface
