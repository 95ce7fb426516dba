#include "sinew/mesh/read_msh.hpp"

#include <gmsh.h>

#include <filesystem>
#include <fstream>
#include <system_error>

#include "sinew/core/error.hpp"
#include "sinew/mesh/gmsh_model.hpp"
#include "sinew/mesh/gmsh_session.hpp"

namespace sinew::mesh {

namespace {

/// Gmsh silently ignores files it cannot open, so check first.
void check_readable(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) {
    throw InputError("mesh file \"" + path + "\" does not exist");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError("mesh file \"" + path + "\" is not a regular file");
  }
  if (!std::ifstream(path, std::ios::binary).good()) {
    throw InputError("mesh file \"" + path + "\" cannot be opened for reading");
  }
}

std::string join(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

}  // namespace

TetMesh read_msh(const std::string& path) {
  check_readable(path);
  const std::string context = "mesh file \"" + path + "\"";
  TetMesh mesh;
  {
    GmshSession gmsh_session;
    gmsh_session.run(context, [&] { gmsh::open(path); });
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
