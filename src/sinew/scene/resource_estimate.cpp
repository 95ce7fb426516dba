/// @file resource_estimate.cpp
/// Mesh size estimated from shapes before meshing (see resource_estimate.hpp).

#include "sinew/scene/resource_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/scene/schema.hpp"

namespace sinew::scene {

namespace {

constexpr double kPi = std::numbers::pi;

/// Sum over the curved surfaces of a shape of A / s^2 (A area, s the refined element size).
double curved_surface_term(const mesh::Shape& shape, const mesh::GenerateOptions& options) {
  if (options.elements_per_turn <= 0) return 0;
  const double h = options.element_size;
  const auto term = [&](double area, double radius) {
    const double s = std::clamp(2 * kPi * radius / options.elements_per_turn, h / 10, h);
    return area / (s * s);
  };
  switch (shape.kind) {
    case mesh::Shape::Kind::Box: return 0;
    case mesh::Shape::Kind::Sphere: return term(4 * kPi * shape.radius * shape.radius, shape.radius);
    case mesh::Shape::Kind::Cylinder: return term(2 * kPi * shape.radius * shape.axis.norm(), shape.radius);
    case mesh::Shape::Kind::Torus:
      return term(4 * kPi * kPi * shape.radius * shape.minor_radius * shape.angle_deg / 360, shape.minor_radius);
    case mesh::Shape::Kind::Union:
    case mesh::Shape::Kind::Difference:
    case mesh::Shape::Kind::Intersection: {
      double sum = 0;
      for (const mesh::Shape& child : shape.children) sum += curved_surface_term(child, options);
      return sum;
    }
  }
  return 0;
}

}  // namespace

double shape_volume_bound(const mesh::Shape& shape) {
  switch (shape.kind) {
    case mesh::Shape::Kind::Box: return (shape.max - shape.min).cwiseMax(0.0).prod();
    case mesh::Shape::Kind::Sphere: return 4.0 / 3.0 * kPi * std::pow(shape.radius, 3);
    case mesh::Shape::Kind::Cylinder: return kPi * shape.radius * shape.radius * shape.axis.norm();
    case mesh::Shape::Kind::Torus:
      // Pappus: the tube's cross-section pi r^2 swept along the centre circle's arc.
      return kPi * shape.minor_radius * shape.minor_radius * 2 * kPi * shape.radius * shape.angle_deg / 360;
    case mesh::Shape::Kind::Union: {
      double sum = 0;
      for (const mesh::Shape& child : shape.children) sum += shape_volume_bound(child);
      return sum;
    }
    case mesh::Shape::Kind::Difference: return shape.children.empty() ? 0 : shape_volume_bound(shape.children.front());
    case mesh::Shape::Kind::Intersection: {
      double smallest = shape.children.empty() ? 0 : shape_volume_bound(shape.children.front());
      for (const mesh::Shape& child : shape.children) smallest = std::min(smallest, shape_volume_bound(child));
      return smallest;
    }
  }
  return 0;
}

double estimated_tets(const std::vector<mesh::Part>& parts, const mesh::GenerateOptions& options) {
  const double h = options.element_size;
  double volume = 0, surface = 0;
  for (const mesh::Part& part : parts) {
    volume += shape_volume_bound(part.shape);
    surface += curved_surface_term(part.shape, options);
  }
  return kTetsPerEdgeCubed * (volume / (h * h * h) + surface);
}

double estimated_tets(const BodyConfig& body) {
  if (!body.mesh.file.empty()) return 0;
  return estimated_tets(body.mesh.parts, body.mesh.generate);
}

void check_resource_limits(const SceneConfig& scene) {
  std::string errors;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const double tets = estimated_tets(scene.bodies[b]);
    if (!(tets > scene.limits.max_tets)) continue;
    const double gigabytes = tets * kBytesPerTet / 1e9;
    errors += (errors.empty() ? "" : "\n") + json_path_key(json_path_key(json_path_index("bodies", b), "mesh"), "generate") +
              fmt::format(": an estimated {:.2g} tets (about {:.2g} GB) at element_size {} exceed the limit of {:.2g} "
                          "tets (raise it with --max-tets); or raise element_size",
                          tets, gigabytes, format_number(scene.bodies[b].mesh.generate.element_size),
                          scene.limits.max_tets);
  }
  if (!errors.empty()) throw InputError(errors);
}

}  // namespace sinew::scene
