/// @file read_shape.cpp
/// Scene JSON -> mesh::Shape: the solids of generated meshes (docs/scene-reference.md, shapes).

#include "sinew/scene/scene_reading.hpp"

namespace sinew::scene::reading {

namespace {

void read_torus(const json& j, const std::string& path, mesh::Shape& shape, ReadErrors& errors) {
  shape.center = to_vector3(j.at("center"));
  shape.axis = to_vector3(j.at("axis"));
  shape.radius = j.at("radius").get<double>();
  shape.minor_radius = j.at("minor_radius").get<double>();
  shape.angle_deg = j.at("angle_deg").get<double>();
  if (!(shape.minor_radius < shape.radius)) {
    errors.add(json_path_key(path, "minor_radius"), "must be < radius (" + format_number(shape.radius) + "), got " +
                                                   format_number(shape.minor_radius));
  }
  if (j.contains("start_direction")) {
    shape.start_direction = to_vector3(j.at("start_direction"));
    const Vector3 axis = shape.axis.normalized();
    const Vector3 start = shape.start_direction.normalized();
    if ((start - start.dot(axis) * axis).norm() < 1e-9) {
      errors.add(json_path_key(path, "start_direction"), "must not be parallel to axis");
    }
  }
}

}  // namespace

mesh::Shape read_shape(const json& j, const std::string& path, ReadErrors& errors) {
  using Kind = mesh::Shape::Kind;
  mesh::Shape shape;
  const std::optional<Kind> kind = kind_key<Kind>(j);
  if (!kind) {
    errors.add(path, "needs one of " + names_list<Kind>());
    return shape;
  }
  shape.kind = *kind;
  const std::string key(name_of(*kind));
  const json& body = j.at(key);
  switch (*kind) {
    case Kind::Box:
      shape.min = to_vector3(body.at("min"));
      shape.max = to_vector3(body.at("max"));
      if (!(shape.min.array() < shape.max.array()).all()) {
        errors.add(json_path_key(path, key), "max must exceed min in every component");
      }
      break;
    case Kind::Sphere:
      shape.center = to_vector3(body.at("center"));
      shape.radius = body.at("radius").get<double>();
      break;
    case Kind::Cylinder:
      shape.center = to_vector3(body.at("base"));
      shape.axis = to_vector3(body.at("axis"));
      shape.radius = body.at("radius").get<double>();
      break;
    case Kind::Torus:
      read_torus(body, json_path_key(path, key), shape, errors);
      break;
    case Kind::Union:
    case Kind::Difference:
    case Kind::Intersection:
      for (std::size_t i = 0; i < body.size(); ++i) {
        shape.children.push_back(read_shape(body[i], json_path_index(json_path_key(path, key), i), errors));
      }
      break;
  }
  if (j.contains("transform")) {
    const json& transform = j.at("transform");
    shape.translation = to_vector3(transform.at("translate"));
    if (transform.contains("rotate")) {
      const json& rotate = transform.at("rotate");
      shape.rotation_axis = to_vector3(rotate.at("axis"));
      shape.rotation_center = to_vector3(rotate.at("center"));
      shape.rotation_angle_deg = rotate.at("angle_deg").get<double>();
    }
  }
  return shape;
}

}  // namespace sinew::scene::reading
