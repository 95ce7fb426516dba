#include "sinew/mesh/read_msh.hpp"

#include <gmsh.h>

#include <new>
#include <stdexcept>

#include "sinew/core/error.hpp"
#include "sinew/mesh/gmsh_model.hpp"
#include "sinew/mesh/gmsh_session.hpp"
#include "sinew/mesh/msh_format_check.hpp"

namespace sinew::mesh {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

}  // namespace

TetMesh read_msh(const std::string& path) {
  // Only a file that passed check_msh_file reaches Gmsh: anything else could be run as a script.
  check_msh_file(path);
  const std::string context = "mesh file \"" + path + "\"";
  TetMesh mesh;
  {
    GmshSession gmsh_session;
    gmsh_session.run(context, [&] {
      try {
        gmsh::open(path);
      } catch (const std::bad_alloc&) {
        throw InputError(context + " is malformed or truncated (a count in it is larger than the "
                                   "file; Gmsh ran out of memory reading it): re-export it from Gmsh");
      } catch (const std::length_error&) {
        throw InputError(context + " is malformed or truncated (a count in it is larger than the "
                                   "file): re-export it from Gmsh");
      }
    });
    mesh = gmsh_session.run(context, [&] {
      const auto other_volume_elements = gmsh_element_type_names(3, {kGmshLinearTetrahedron});
      if (!other_volume_elements.empty()) {
        throw InputError(context + " holds volume elements other than linear tetrahedra (" +
                         join(other_volume_elements) +
                         "); sinew supports only linear tetrahedra (Gmsh element type 4): "
                         "remesh with Mesh.ElementOrder = 1 and without recombination");
      }
      TetMesh model_mesh;
      try {
        model_mesh = tet_mesh_from_gmsh_model();
      } catch (const InputError& e) {
        throw InputError(context + ": " + e.what());
      }
      if (model_mesh.num_tets() == 0) {
        const std::string found = join(gmsh_element_type_names());
        throw InputError(context + " holds no linear tetrahedra (Gmsh element type 4); it has " +
                         (found.empty() ? std::string("no elements") : "only: " + found) +
                         " (is it a volume mesh? mesh it in 3D, with Mesh.ElementOrder = 1)");
      }
      return model_mesh;
    });
  }
  validate(mesh, path);
  return mesh;
}

}  // namespace sinew::mesh
