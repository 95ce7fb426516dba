#include "sinew/mesh/generate.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
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

/// Curved surfaces get at least this many elements per full turn (Mesh.MeshSizeFromCurvature),
/// refining down to element_size * kMinSizeFactor, so a hole much thinner than element_size is
/// still resolved.
constexpr double kElementsPerTurn = 12;
constexpr double kMinSizeFactor = 0.1;

std::string kind_name(Shape::Kind kind) {
  switch (kind) {
    case Shape::Kind::Box:
      return "box";
    case Shape::Kind::Cylinder:
      return "cylinder";
    case Shape::Kind::Sphere:
      return "sphere";
    case Shape::Kind::Union:
      return "union";
    case Shape::Kind::Difference:
      return "difference";
  }
  return "shape";
}

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

  /// The volumes (dimension 3 entities) of `shape`.
  gmsh::vectorpair build(const Shape& shape, const std::string& path) {
    const std::string where = "part \"" + part_name_ + "\", " + kind_name(shape.kind) +
                              (path.empty() ? "" : " at " + path);
    const auto fail = [&where](const std::string& problem) {
      throw InputError(where + ": " + problem);
    };
    const bool is_boolean =
        shape.kind == Shape::Kind::Union || shape.kind == Shape::Kind::Difference;
    if (!is_boolean && !shape.children.empty()) fail("only unions and differences have children");

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
      case Shape::Kind::Union:
      case Shape::Kind::Difference: {
        if (shape.children.empty()) fail("needs at least one child shape");
        const std::string children_path = path.empty() ? "children" : path + ".children";
        gmsh::vectorpair objects = build(shape.children[0], children_path + "[0]");
        gmsh::vectorpair tools;
        for (std::size_t i = 1; i < shape.children.size(); ++i) {
          const auto child =
              build(shape.children[i], children_path + "[" + std::to_string(i) + "]");
          tools.insert(tools.end(), child.begin(), child.end());
        }
        if (tools.empty()) return objects;
        gmsh::vectorpair result = session_.run(where, [&] {
          return shape.kind == Shape::Kind::Union ? fragment_union(objects, tools)
                                                  : fragment_difference(objects, tools);
        });
        if (result.empty()) fail("the result is empty (the subtracted shapes cover the first one)");
        return result;
      }
    }
    fail("unknown shape kind");
    return {};
  }

 private:
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
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", kElementsPerTurn);
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
