#include "sinew/mesh/read_msh.hpp"

#include <gmsh.h>

#include <new>
#include <stdexcept>

#include "sinew/core/error.hpp"
#include "sinew/mesh/gmsh_model.hpp"
#include "sinew/mesh/gmsh_session.hpp"
#include "sinew/mesh/msh_format_check.hpp"
#include "sinew/mesh/private_file_copy.hpp"

namespace sinew::mesh {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace

TetMesh read_msh(const std::string& path) {
  // Only a genuine MSH file reaches Gmsh, which would run anything else as a script; and Gmsh
  // reads a private copy, the very bytes checked, with no "<name>.opt" script beside it (Gmsh
  // runs one when it exists). See docs/input-safety.md.
  check_msh_path(path);
  const PrivateFileCopy copy(path, "mesh.msh", kMaxMshFileBytes);
  check_msh_content(copy.path(), path);
  const std::string context = "mesh file \"" + path + "\"";
  TetMesh mesh;
  try {
    GmshSession gmsh_session;
    gmsh_session.run(context, [&] {
      try {
        gmsh::open(copy.path());
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
  } catch (const InputError& error) {
    // Gmsh's messages name the copy it read.
    throw InputError(replace_all(error.what(), copy.path(), path));
  }
  validate(mesh, path);
  return mesh;
}

}  // namespace sinew::mesh
