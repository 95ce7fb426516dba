#include "sinew/mesh/generate.hpp"

#include <gmsh.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/mesh/gmsh_model.hpp"
#include "sinew/mesh/gmsh_session.hpp"

namespace sinew::mesh {

namespace {

namespace occ = gmsh::model::occ;

/// Spheres and cylinders are turned about their centre (sphere) or their own axis (cylinder) by
/// this generic angle, so that the seam and poles of their OpenCASCADE parametrisation do not
/// land on the axis-aligned edges and faces of boxes. The geometry is unchanged. Without the
/// turn, Gmsh 4.8 fails on e.g. a box united with a sphere centred on one of its corners ("The
/// 1D mesh seems not to be forming a closed loop", "Impossible to mesh periodic surface"): 3-4
/// of 100 random box/sphere/cylinder unions and differences with features on box corners, edges
/// and faces failed, none of 400 with the turn and fragment-based booleans (see ShapeBuilder).
constexpr double kSeamRotationRadians = 0.7;
/// Axis of the sphere's turn: generic, not in any coordinate plane.
const Vector3 kSphereSeamRotationAxis = Vector3(1, 2, 3).normalized();

/// Curved surfaces are refined for GenerateOptions::elements_per_turn down to element_size *
/// kMinSizeFactor, so a hole much thinner than element_size is still resolved.
constexpr double kMinSizeFactor = 0.1;

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

/// The default reference direction of a torus is +x projected onto its plane, unless that
/// projection is shorter than this (axis within 0.06 degrees of x); then +y projected.
constexpr double kMinReferenceProjection = 1e-3;

std::string kind_name(Shape::Kind kind) { return std::string(name_of(kind)); }

/// Six significant digits without trailing zeros: 0.1 rather than std::to_string's 0.100000.
std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string format_vector(const Vector3& v) {
  return "(" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) +
         ")";
}

/// Builds shapes into the OpenCASCADE model; messages name the part and the path in its tree.
class ShapeBuilder {
 public:
  ShapeBuilder(GmshSession& session, std::string part_name)
      : session_(session), part_name_(std::move(part_name)) {}

  /// The volumes (dimension 3 entities) of `shape`, its transform applied.
  gmsh::vectorpair build(const Shape& shape, const std::string& path) {
    const std::string where = "part \"" + part_name_ + "\", " + kind_name(shape.kind) +
                              (path.empty() ? "" : " at " + path);
    const auto fail = [&where](const std::string& problem) {
      throw InputError(where + ": " + problem);
    };
    check_transform(shape, fail);  // before building, so that errors come without Gmsh work
    gmsh::vectorpair volumes = build_untransformed(shape, path, where, fail);
    session_.run(where + ", transform", [&] { apply_transform(shape, volumes); });
    return volumes;
  }

 private:
  template <class Fail>
  gmsh::vectorpair build_untransformed(const Shape& shape, const std::string& path,
                                       const std::string& where, const Fail& fail) {
    const bool is_boolean = shape.kind == Shape::Kind::Union ||
                            shape.kind == Shape::Kind::Difference ||
                            shape.kind == Shape::Kind::Intersection;
    if (!is_boolean && !shape.children.empty()) {
      fail("only unions, differences and intersections have children");
    }

    switch (shape.kind) {
      case Shape::Kind::Box: {
        const Vector3 size = shape.max - shape.min;
        if (!shape.min.allFinite() || !shape.max.allFinite() || (size.array() <= 0).any()) {
          fail("max " + format_vector(shape.max) + " must exceed min " + format_vector(shape.min) +
               " in every coordinate");
        }
        return session_.run(where, [&] {
          const int tag = occ::addBox(shape.min.x(), shape.min.y(), shape.min.z(), size.x(),
                                      size.y(), size.z());
          return gmsh::vectorpair{{3, tag}};
        });
      }
      case Shape::Kind::Cylinder: {
        check_radius(shape, fail);
        const double height = shape.axis.norm();
        if (!shape.center.allFinite() || !std::isfinite(height) || height <= 0) {
          fail("the axis must be a finite non-zero vector (base centre to top centre), got " +
               format_vector(shape.axis));
        }
        return session_.run(where, [&] {
          const int tag =
              occ::addCylinder(shape.center.x(), shape.center.y(), shape.center.z(), shape.axis.x(),
                               shape.axis.y(), shape.axis.z(), shape.radius);
          occ::rotate({{3, tag}}, shape.center.x(), shape.center.y(), shape.center.z(),
                      shape.axis.x(), shape.axis.y(), shape.axis.z(), kSeamRotationRadians);
          return gmsh::vectorpair{{3, tag}};
        });
      }
      case Shape::Kind::Sphere: {
        check_radius(shape, fail);
        if (!shape.center.allFinite()) fail("the centre must be finite");
        return session_.run(where, [&] {
          const int tag =
              occ::addSphere(shape.center.x(), shape.center.y(), shape.center.z(), shape.radius);
          const Vector3& axis = kSphereSeamRotationAxis;
          occ::rotate({{3, tag}}, shape.center.x(), shape.center.y(), shape.center.z(), axis.x(),
                      axis.y(), axis.z(), kSeamRotationRadians);
          return gmsh::vectorpair{{3, tag}};
        });
      }
      case Shape::Kind::Torus:
        return build_torus(shape, where, fail);
      case Shape::Kind::Union:
      case Shape::Kind::Difference:
      case Shape::Kind::Intersection: {
        if (shape.children.empty()) fail("needs at least one child shape");
        if (shape.kind == Shape::Kind::Intersection && shape.children.size() < 2) {
          fail("needs at least two child shapes");
        }
        const std::string children_path = path.empty() ? "children" : path + ".children";
        gmsh::vectorpair objects = build(shape.children[0], children_path + "[0]");
        gmsh::vectorpair tools;
        // child_of_input[k]: the child that input volume k (objects, then tools) comes from.
        std::vector<std::size_t> child_of_input(objects.size(), 0);
        for (std::size_t i = 1; i < shape.children.size(); ++i) {
          const auto child =
              build(shape.children[i], children_path + "[" + std::to_string(i) + "]");
          tools.insert(tools.end(), child.begin(), child.end());
          child_of_input.insert(child_of_input.end(), child.size(), i);
        }
        if (tools.empty()) return objects;
        gmsh::vectorpair result = session_.run(where, [&] {
          switch (shape.kind) {
            case Shape::Kind::Union:
              return fragment_union(objects, tools);
            case Shape::Kind::Difference:
              return fragment_difference(objects, tools);
            default:
              return fragment_intersection(objects, tools, child_of_input, shape.children.size());
          }
        });
        if (result.empty()) {
          fail(shape.kind == Shape::Kind::Difference
                   ? "the result is empty (the subtracted shapes cover the first one)"
                   : "the result is empty (the shapes have no volume in common)");
        }
        return result;
      }
    }
    fail("unknown shape kind");
    return {};
  }

  template <class Fail>
  static void check_transform(const Shape& shape, const Fail& fail) {
    if (!std::isfinite(shape.rotation_angle_deg)) {
      fail("the rotation angle must be finite, got " + format_number(shape.rotation_angle_deg));
    }
    if (!shape.rotation_center.allFinite()) {
      fail("the rotation center must be finite, got " + format_vector(shape.rotation_center));
    }
    const double axis_length = shape.rotation_axis.norm();
    if (shape.rotation_angle_deg != 0 && (!std::isfinite(axis_length) || axis_length <= 0)) {
      fail("the rotation axis must be a finite non-zero vector, got " +
           format_vector(shape.rotation_axis));
    }
    if (!shape.translation.allFinite()) {
      fail("the translation must be finite, got " + format_vector(shape.translation));
    }
  }

  /// The shape's rigid transform: rotation about its axis, then translation.
  static void apply_transform(const Shape& shape, const gmsh::vectorpair& volumes) {
    if (shape.rotation_angle_deg != 0) {
      const Vector3& c = shape.rotation_center;
      const Vector3 a = shape.rotation_axis.normalized();
      occ::rotate(volumes, c.x(), c.y(), c.z(), a.x(), a.y(), a.z(),
                  shape.rotation_angle_deg * kRadiansPerDegree);
    }
    if (!shape.translation.isZero(0)) {
      occ::translate(volumes, shape.translation.x(), shape.translation.y(), shape.translation.z());
    }
  }

  /// Unit reference direction of a torus: `start_direction`, or the default, made
  /// perpendicular to the unit `axis`.
  template <class Fail>
  static Vector3 torus_reference(const Shape& shape, const Vector3& axis, const Fail& fail) {
    const auto perpendicular = [&axis](const Vector3& v) {
      return Vector3(v - v.dot(axis) * axis);
    };
    if (!shape.start_direction.isZero(0)) {
      const Vector3 start = perpendicular(shape.start_direction);
      if (!(start.norm() > 1e-9 * shape.start_direction.norm())) {
        fail("the start direction " + format_vector(shape.start_direction) +
             " must not be parallel to the axis " + format_vector(shape.axis));
      }
      return start.normalized();
    }
    const Vector3 from_x = perpendicular(Vector3::UnitX());
    if (from_x.norm() >= kMinReferenceProjection) return from_x.normalized();
    return perpendicular(Vector3::UnitY()).normalized();
  }

  /// OpenCASCADE sweeps a torus about +z from +x; it is built so at the origin, then turned so
  /// that (x, y, z) go to (reference, axis x reference, axis), then moved to the centre.
  template <class Fail>
  gmsh::vectorpair build_torus(const Shape& shape, const std::string& where, const Fail& fail) {
    check_radius(shape, fail);
    if (!std::isfinite(shape.minor_radius) || shape.minor_radius <= 0 ||
        !(shape.minor_radius < shape.radius)) {
      fail("the minor radius must be positive and less than the radius " +
           format_number(shape.radius) + ", got " + format_number(shape.minor_radius));
    }
    if (!std::isfinite(shape.angle_deg) || shape.angle_deg <= 0 || shape.angle_deg > 360) {
      fail("the angle must be in (0, 360] degrees, got " + format_number(shape.angle_deg));
    }
    const double axis_length = shape.axis.norm();
    if (!shape.center.allFinite() || !std::isfinite(axis_length) || axis_length <= 0) {
      fail("the center must be finite and the axis a finite non-zero vector, got center " +
           format_vector(shape.center) + ", axis " + format_vector(shape.axis));
    }
    if (!shape.start_direction.allFinite()) {
      fail("the start direction must be finite, got " + format_vector(shape.start_direction));
    }
    const Vector3 e3 = shape.axis / axis_length;
    Vector3 e1 = torus_reference(shape, e3, fail);
    const bool full_turn = shape.angle_deg == 360;
    // A full torus is the same solid whatever its start: turn its seam off the reference plane,
    // which scenes tend to align with box faces (see kSeamRotationRadians).
    if (full_turn) e1 = Eigen::AngleAxisd(kSeamRotationRadians, e3) * e1;
    Matrix3 frame;
    frame.col(0) = e1;
    frame.col(1) = e3.cross(e1);
    frame.col(2) = e3;
    const Eigen::AngleAxisd turn(frame);
    return session_.run(where, [&] {
      const int tag =
          occ::addTorus(0, 0, 0, shape.radius, shape.minor_radius, -1,
                        full_turn ? 2 * std::numbers::pi : shape.angle_deg * kRadiansPerDegree);
      const gmsh::vectorpair volumes{{3, tag}};
      if (turn.angle() != 0) {
        occ::rotate(volumes, 0, 0, 0, turn.axis().x(), turn.axis().y(), turn.axis().z(),
                    turn.angle());
      }
      occ::translate(volumes, shape.center.x(), shape.center.y(), shape.center.z());
      return volumes;
    });
  }

  template <class Fail>
  static void check_radius(const Shape& shape, const Fail& fail) {
    if (!std::isfinite(shape.radius) || shape.radius <= 0) {
      fail("the radius must be positive, got " + format_number(shape.radius));
    }
  }

  /// Union as boolean fragments: every piece is kept, so the result may be several volumes
  /// sharing faces (meshed conformingly). More robust in Gmsh 4.8 than occ::fuse, which leaves
  /// broken faces e.g. for a box fused with a sphere poking out of all its faces.
  static gmsh::vectorpair fragment_union(const gmsh::vectorpair& objects,
                                         const gmsh::vectorpair& tools) {
    gmsh::vectorpair pieces;
    std::vector<gmsh::vectorpair> pieces_of_input;
    occ::fragment(objects, tools, pieces, pieces_of_input);
    return pieces;
  }

  /// Intersection as boolean fragments (like the union and difference, and because a child may
  /// be several volumes): the pieces that come from every child are kept, the others removed.
  /// `child_of_input` names the child of each input volume, objects first, then tools.
  static gmsh::vectorpair fragment_intersection(const gmsh::vectorpair& objects,
                                                const gmsh::vectorpair& tools,
                                                const std::vector<std::size_t>& child_of_input,
                                                std::size_t num_children) {
    gmsh::vectorpair pieces;
    std::vector<gmsh::vectorpair> pieces_of_input;
    occ::fragment(objects, tools, pieces, pieces_of_input);
    std::map<std::pair<int, int>, std::set<std::size_t>> children_of_piece;
    for (std::size_t input = 0; input < pieces_of_input.size() && input < child_of_input.size();
         ++input) {
      for (const auto& piece : pieces_of_input[input]) {
        children_of_piece[piece].insert(child_of_input[input]);
      }
    }
    gmsh::vectorpair kept, removed;
    for (const auto& piece : pieces) {
      const auto found = children_of_piece.find(piece);
      const bool in_all = found != children_of_piece.end() && found->second.size() == num_children;
      (in_all ? kept : removed).push_back(piece);
    }
    if (!removed.empty()) occ::remove(removed, /*recursive=*/true);
    return kept;
  }

  /// Difference as boolean fragments: the pieces of the objects that are not pieces of any
  /// tool are kept, the others removed.
  static gmsh::vectorpair fragment_difference(const gmsh::vectorpair& objects,
                                              const gmsh::vectorpair& tools) {
    gmsh::vectorpair pieces;
    std::vector<gmsh::vectorpair> pieces_of_input;
    occ::fragment(objects, tools, pieces, pieces_of_input);
    std::set<std::pair<int, int>> in_tools;
    for (std::size_t input = objects.size(); input < pieces_of_input.size(); ++input) {
      in_tools.insert(pieces_of_input[input].begin(), pieces_of_input[input].end());
    }
    gmsh::vectorpair kept;
    for (std::size_t input = 0; input < objects.size() && input < pieces_of_input.size(); ++input) {
      for (const auto& piece : pieces_of_input[input]) {
        if (!in_tools.count(piece) && std::find(kept.begin(), kept.end(), piece) == kept.end()) {
          kept.push_back(piece);
        }
      }
    }
    gmsh::vectorpair removed;
    for (const auto& piece : pieces) {
      if (std::find(kept.begin(), kept.end(), piece) == kept.end()) removed.push_back(piece);
    }
    if (!removed.empty()) occ::remove(removed, /*recursive=*/true);
    return kept;
  }

  GmshSession& session_;
  std::string part_name_;
};

void check_inputs(const std::vector<Part>& parts, const GenerateOptions& options) {
  if (parts.empty()) throw InputError("generate_mesh: no parts to mesh");
  if (!std::isfinite(options.element_size) || options.element_size <= 0) {
    throw InputError("generate_mesh: element_size must be positive, got " +
                     format_number(options.element_size));
  }
  if (options.optimize_passes < 0) {
    throw InputError("generate_mesh: optimize_passes must be >= 0, got " +
                     std::to_string(options.optimize_passes));
  }
  if (!std::isfinite(options.elements_per_turn) || options.elements_per_turn < 0) {
    throw InputError("generate_mesh: elements_per_turn must be >= 0, got " + format_number(options.elements_per_turn));
  }
  if (options.threads < 1) {
    throw InputError("generate_mesh: threads must be >= 1, got " + std::to_string(options.threads));
  }
  std::set<std::string> names;
  for (const auto& part : parts) {
    if (part.region.empty()) throw InputError("generate_mesh: a part has an empty region name");
    if (!names.insert(part.region).second) {
      throw InputError("generate_mesh: two parts are named \"" + part.region +
                       "\"; region names must be unique");
    }
  }
}

/// Fragments the parts' volumes against each other so that they share interfaces; returns the
/// volume tags of each part (overlaps go to the part listed first).
std::vector<std::vector<int>> fragment_parts(GmshSession& session,
                                             const std::vector<gmsh::vectorpair>& part_volumes,
                                             const std::vector<Part>& parts) {
  std::vector<std::vector<int>> volumes_of_part(parts.size());
  if (parts.size() == 1) {
    for (const auto& [dim, tag] : part_volumes[0]) volumes_of_part[0].push_back(tag);
    return volumes_of_part;
  }
  gmsh::vectorpair objects = part_volumes[0];
  gmsh::vectorpair tools;
  std::vector<std::size_t> part_of_input(part_volumes[0].size(), 0);
  for (std::size_t p = 1; p < parts.size(); ++p) {
    tools.insert(tools.end(), part_volumes[p].begin(), part_volumes[p].end());
    part_of_input.insert(part_of_input.end(), part_volumes[p].size(), p);
  }
  std::vector<gmsh::vectorpair> output_of_input;
  session.run("fragmenting the parts together", [&] {
    gmsh::vectorpair out;
    occ::fragment(objects, tools, out, output_of_input);
  });
  std::set<int> assigned;
  for (std::size_t input = 0; input < output_of_input.size() && input < part_of_input.size();
       ++input) {
    for (const auto& [dim, tag] : output_of_input[input]) {
      if (dim == 3 && assigned.insert(tag).second) {
        volumes_of_part[part_of_input[input]].push_back(tag);
      }
    }
  }
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (volumes_of_part[p].empty()) {
      throw InputError("part \"" + parts[p].region +
                       "\" lies entirely inside parts listed before it, which take overlaps; "
                       "it gets no volume of its own");
    }
  }
  return volumes_of_part;
}

void set_mesh_options(const GenerateOptions& options) {
  const double size = options.element_size;
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", size * kMinSizeFactor);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", options.elements_per_turn);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.Algorithm", 6);    // Frontal-Delaunay surfaces
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay volumes
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.RandomSeed", 1);
  gmsh::option::setNumber("Mesh.Optimize", 0);  // passes are run explicitly below
  gmsh::option::setNumber("Mesh.OptimizeNetgen", 0);
}

std::string describe_parts(const std::vector<Part>& parts) {
  std::string names;
  for (const auto& part : parts) names += (names.empty() ? "" : ", ") + part.region;
  return std::string(parts.size() == 1 ? "part " : "parts ") + names;
}

}  // namespace

TetMesh generate_mesh(const std::vector<Part>& parts, const GenerateOptions& options) {
  check_inputs(parts, options);
  const std::string what = describe_parts(parts);
  TetMesh mesh;
  {
    GmshSession session({.threads = options.threads});
    std::vector<gmsh::vectorpair> part_volumes;
    for (const auto& part : parts) {
      part_volumes.push_back(ShapeBuilder(session, part.region).build(part.shape, ""));
    }
    const auto volumes_of_part = fragment_parts(session, part_volumes, parts);
    session.run("defining the regions", [&] {
      occ::synchronize();
      for (std::size_t p = 0; p < parts.size(); ++p) {
        const int group = static_cast<int>(p) + 1;
        gmsh::model::addPhysicalGroup(3, volumes_of_part[p], group);
        gmsh::model::setPhysicalName(3, group, parts[p].region);
      }
    });
    set_mesh_options(options);
    session.run("meshing " + what + " with element_size " + format_number(options.element_size) +
                    " failed (features much thinner than element_size, or surfaces touching "
                    "along a line or at a point, are usual causes)",
                [&] {
                  gmsh::model::mesh::generate(3);
                  if (options.optimize_passes > 0) {
                    gmsh::model::mesh::optimize("", false, options.optimize_passes);
                  }
                });
    mesh = session.run("reading the generated mesh", [] { return tet_mesh_from_gmsh_model(); });
  }
  if (mesh.num_tets() == 0) throw InputError(what + ": Gmsh produced no tetrahedra");

  for (Index r = 0; r < static_cast<Index>(mesh.region_names.size()); ++r) {
    std::vector<Index> region_tets;
    for (Index t = 0; t < mesh.num_tets(); ++t) {
      if (mesh.region(t) == r) region_tets.push_back(t);
    }
    const Triangles surface = boundary_triangles(mesh.tets(region_tets, Eigen::all));
    const std::string set_name = mesh.region_names[r] + ".surface";
    mesh.face_sets[set_name] = surface;
    std::vector<Index> nodes(surface.data(), surface.data() + surface.size());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    mesh.node_sets[set_name] = std::move(nodes);
  }
  logger().debug("{}: {} nodes, {} tets", what, mesh.num_nodes(), mesh.num_tets());
  validate(mesh, what);
  return mesh;
}

}  // namespace sinew::mesh
