/// @file solid.cpp

#include "sinew/surface/solid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sinew/core/error.hpp"

namespace sinew::surface {

namespace {

const ClosedSurface& find_surface(const SurfaceLibrary& library, const std::string& name) { return library.at(name); }

/// Orthonormal frame of an ellipsoid: columns u, v, u x v.
Matrix3 ellipsoid_frame(const Solid& solid) {
  const Vector3 u = solid.axis_u.normalized();
  const Vector3 v = (solid.axis_v - solid.axis_v.dot(u) * u).normalized();
  Matrix3 frame;
  frame << u, v, u.cross(v);
  return frame;
}

Bounds infinite_bounds() {
  Bounds b;
  b.min = Vector3::Constant(-std::numeric_limits<double>::infinity());
  b.max = Vector3::Constant(std::numeric_limits<double>::infinity());
  return b;
}

}  // namespace

double segment_distance(const Vector3& a, const Vector3& b, const Vector3& x) {
  const Vector3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (x - (a + s * ab)).norm();
}

void check_solid(const Solid& solid, const SurfaceLibrary& library, const std::string& what) {
  using Kind = Solid::Kind;
  const std::string kind(name_of(solid.kind));
  for (const std::string& name : solid.surfaces) {
    if (library.count(name) == 0) throw InputError(what + ": " + kind + " names an unknown surface \"" + name + "\"");
  }
  switch (solid.kind) {
    case Kind::Surface:
      if (solid.surfaces.size() != 1) throw InputError(what + ": a surface solid names exactly one surface");
      break;
    case Kind::Offset:
      if (solid.surfaces.empty()) throw InputError(what + ": an offset needs at least one surface");
      if (!std::isfinite(solid.distance)) throw InputError(what + ": the offset distance must be finite");
      break;
    case Kind::Box:
      if (!(solid.min.array() < solid.max.array()).all()) throw InputError(what + ": a box's max must exceed its min");
      break;
    case Kind::Capsule:
      if (!(solid.radius > 0)) throw InputError(what + ": a capsule's radius must be > 0");
      break;
    case Kind::Ellipsoid:
      if (!(solid.semi_axes.array() > 0).all()) throw InputError(what + ": an ellipsoid's semi-axes must be > 0");
      if (solid.axis_u.norm() == 0 || (solid.axis_v - solid.axis_v.dot(solid.axis_u.normalized()) * solid.axis_u.normalized()).norm() < 1e-9) {
        throw InputError(what + ": an ellipsoid's axis_u must be non-zero and axis_v not parallel to it");
      }
      break;
    case Kind::HalfSpace:
      if (!(solid.normal.norm() > 0)) throw InputError(what + ": a half-space's normal must be non-zero");
      break;
    case Kind::Union:
    case Kind::Difference:
    case Kind::Intersection:
      if (solid.children.empty()) throw InputError(what + ": " + kind + " needs at least one solid");
      for (std::size_t i = 0; i < solid.children.size(); ++i) {
        check_solid(solid.children[i], library, what + "/" + kind + "[" + std::to_string(i) + "]");
      }
      break;
  }
}

double union_signed_distance(const std::vector<std::string>& surfaces, const SurfaceLibrary& library,
                             const Vector3& point) {
  double distance = std::numeric_limits<double>::infinity();
  for (const std::string& name : surfaces) distance = std::min(distance, find_surface(library, name).signed_distance(point));
  return distance;
}

bool solid_contains(const Solid& solid, const SurfaceLibrary& library, const Vector3& x) {
  using Kind = Solid::Kind;
  switch (solid.kind) {
    case Kind::Surface:
      return find_surface(library, solid.surfaces.front()).contains(x);
    case Kind::Offset: {
      if (solid.distance > 0) {
        for (const std::string& name : solid.surfaces) {
          const Bounds b = find_surface(library, name).bounds();
          // Near the surface, or inside it (only then is the costlier inside test needed).
          if (((x.array() >= b.min.array() - solid.distance) && (x.array() <= b.max.array() + solid.distance)).all() &&
              (find_surface(library, name).distance(x) <= solid.distance || find_surface(library, name).contains(x))) {
            return true;
          }
        }
        return false;
      }
      // Shrunk: inside one of the surfaces and farther than -distance from every one of them.
      bool inside = false;
      for (const std::string& name : solid.surfaces) inside = inside || find_surface(library, name).contains(x);
      return inside && union_signed_distance(solid.surfaces, library, x) <= solid.distance;
    }
    case Kind::Box:
      return (x.array() >= solid.min.array()).all() && (x.array() <= solid.max.array()).all();
    case Kind::Capsule:
      return segment_distance(solid.a, solid.b, x) <= solid.radius;
    case Kind::Ellipsoid: {
      const Vector3 local = ellipsoid_frame(solid).transpose() * (x - solid.a);
      return local.cwiseQuotient(solid.semi_axes).squaredNorm() <= 1.0;
    }
    case Kind::HalfSpace:
      return (x - solid.point).dot(solid.normal) <= 0;
    case Kind::Union:
      return std::any_of(solid.children.begin(), solid.children.end(),
                         [&](const Solid& child) { return solid_contains(child, library, x); });
    case Kind::Intersection:
      return std::all_of(solid.children.begin(), solid.children.end(),
                         [&](const Solid& child) { return solid_contains(child, library, x); });
    case Kind::Difference:
      if (!solid_contains(solid.children.front(), library, x)) return false;
      return std::none_of(solid.children.begin() + 1, solid.children.end(),
                          [&](const Solid& child) { return solid_contains(child, library, x); });
  }
  return false;
}

Bounds solid_bounds(const Solid& solid, const SurfaceLibrary& library) {
  using Kind = Solid::Kind;
  Bounds bounds;
  switch (solid.kind) {
    case Kind::Surface:
      return find_surface(library, solid.surfaces.front()).bounds();
    case Kind::Offset:
      for (const std::string& name : solid.surfaces) bounds.extend(find_surface(library, name).bounds());
      bounds.min.array() -= std::max(solid.distance, 0.0);
      bounds.max.array() += std::max(solid.distance, 0.0);
      return bounds;
    case Kind::Box:
      bounds.extend(solid.min);
      bounds.extend(solid.max);
      return bounds;
    case Kind::Capsule:
      bounds.extend(solid.a.array().min(solid.b.array()).matrix() - Vector3::Constant(solid.radius));
      bounds.extend(solid.a.array().max(solid.b.array()).matrix() + Vector3::Constant(solid.radius));
      return bounds;
    case Kind::Ellipsoid: {
      const Matrix3 frame = ellipsoid_frame(solid);
      // Half-extent along axis i: sqrt(sum_k (frame(i,k) semi_k)^2).
      const Vector3 half = (frame.array().square().matrix() * solid.semi_axes.array().square().matrix()).cwiseSqrt();
      bounds.extend(solid.a - half);
      bounds.extend(solid.a + half);
      return bounds;
    }
    case Kind::HalfSpace:
      return infinite_bounds();
    case Kind::Union:
      for (const Solid& child : solid.children) bounds.extend(solid_bounds(child, library));
      return bounds;
    case Kind::Difference:
      return solid_bounds(solid.children.front(), library);
    case Kind::Intersection: {
      bounds = infinite_bounds();
      for (const Solid& child : solid.children) {
        const Bounds b = solid_bounds(child, library);
        bounds.min = bounds.min.cwiseMax(b.min);
        bounds.max = bounds.max.cwiseMin(b.max);
      }
      return bounds;
    }
  }
  return bounds;
}

}  // namespace sinew::surface
