/// @file assimp_import.cpp
/// Assimp behind a memory-only IOSystem: the importer sees the checked bytes under the file's
/// own name and nothing else, so no second file is ever opened and nothing is executed.
/// Assimp's DefaultLogger is never created: its NullLogger prints nothing.

#include "sinew/surface/assimp_import.hpp"

#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <new>

#include "sinew/core/error.hpp"
#include "sinew/surface/reader_guards.hpp"

namespace sinew::surface {
namespace {

/// Serves one in-memory file and refuses every other name, recording what was asked for.
class SingleFileIOSystem : public Assimp::IOSystem {
 public:
  SingleFileIOSystem(std::string name, const std::vector<std::uint8_t>& bytes) : name_(std::move(name)), bytes_(bytes) {}

  bool Exists(const char* file) const override { return file != nullptr && name_ == file; }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    const std::string wanted = file == nullptr ? "" : file;
    const std::string m = mode == nullptr ? "" : mode;
    if (wanted != name_ || m.find_first_of("wa+") != std::string::npos) {
      refused_.push_back(wanted);
      return nullptr;
    }
    return new Assimp::MemoryIOStream(bytes_.data(), bytes_.size(), false);
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

  const std::vector<std::string>& refused() const { return refused_; }

 private:
  std::string name_;
  const std::vector<std::uint8_t>& bytes_;
  std::vector<std::string> refused_;
};

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

/// Every (mesh index, world transform) pair of the node tree.
void collect_instances(const aiNode* node, const Eigen::Matrix4d& parent,
                       std::vector<std::vector<Eigen::Matrix4d>>& instances, int depth) {
  if (node == nullptr || depth > 1000) return;
  const Eigen::Matrix4d world = parent * to_eigen(node->mTransformation);
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    if (node->mMeshes[i] < instances.size()) instances[node->mMeshes[i]].push_back(world);
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) collect_instances(node->mChildren[c], world, instances, depth + 1);
}

std::string mesh_name(const aiMesh& mesh, unsigned index) {
  const std::string name(mesh.mName.C_Str());
  return name.empty() ? fmt::format("mesh{}", index) : name;
}

/// Appends one instance of `mesh` placed by `world` (4 x 4, column vectors) to `out`.
void append_instance(const SurfaceFile& file, const aiMesh& mesh, const Eigen::Matrix4d& world, ImportedMesh& out) {
  const Index base = static_cast<Index>(out.vertices.rows());
  const unsigned nv = mesh.mNumVertices;
  if (nv > 0 && mesh.mVertices == nullptr) {
    throw InputError(fmt::format("surface file '{}', mesh '{}': no vertex positions", file.path, out.name));
  }
  if (static_cast<std::uint64_t>(base) + nv > static_cast<std::uint64_t>(std::numeric_limits<Index>::max())) {
    throw InputError(fmt::format("surface file '{}', mesh '{}': too many vertices", file.path, out.name));
  }
  out.vertices.conservativeResize(base + static_cast<Index>(nv), 3);
  for (unsigned v = 0; v < nv; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    const Eigen::Vector4d local(p.x, p.y, p.z, 1.0);
    if (!local.allFinite()) {
      throw InputError(fmt::format("surface file '{}', mesh '{}': vertex {} is not finite ({}, {}, {})", file.path,
                                   out.name, v, p.x, p.y, p.z));
    }
    const Eigen::Vector4d placed = world * local;
    if (!placed.allFinite()) {
      throw InputError(fmt::format("surface file '{}', mesh '{}': vertex {} is not finite after the node transform",
                                   file.path, out.name, v));
    }
    out.vertices.row(base + static_cast<Index>(v)) = placed.head<3>().transpose();
  }
  std::vector<Index> corners;
  corners.reserve(static_cast<std::size_t>(mesh.mNumFaces) * 3);
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3 || face.mIndices == nullptr) continue;  // points and lines
    for (unsigned k = 0; k < 3; ++k) {
      if (face.mIndices[k] >= nv) {
        throw InputError(fmt::format("surface file '{}', mesh '{}': triangle {} refers to vertex {} of {}", file.path,
                                     out.name, f, face.mIndices[k], nv));
      }
      corners.push_back(base + static_cast<Index>(face.mIndices[k]));
    }
  }
  const Index old = static_cast<Index>(out.triangles.rows());
  const Index added = static_cast<Index>(corners.size() / 3);
  out.triangles.conservativeResize(old + added, 3);
  for (Index t = 0; t < added; ++t) {
    for (int k = 0; k < 3; ++k) out.triangles(old + t, k) = corners[static_cast<std::size_t>(3 * t + k)];
  }
}

/// Checks the faces of the scene as the format reader left it, before any post-processing step
/// reads vertices through them (Assimp's readers do not all check the indices), and sets each
/// mesh's primitive types from its faces (a reader may leave them unset, and Assimp 5.2's
/// triangulation then aborts on an assertion for faces of fewer than three corners).
void check_faces(const SurfaceFile& file, aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    if (scene.mMeshes[m] == nullptr) continue;
    aiMesh& mesh = *scene.mMeshes[m];
    unsigned types = 0;
    if (mesh.mNumFaces > 0 && mesh.mFaces == nullptr) {
      throw InputError(fmt::format("surface file '{}', mesh '{}': faces without indices", file.path, mesh_name(mesh, m)));
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices > 0 && face.mIndices == nullptr) {
        throw InputError(fmt::format("surface file '{}', mesh '{}': face {} without indices", file.path,
                                     mesh_name(mesh, m), f));
      }
      if (face.mNumIndices == 0) {
        throw InputError(fmt::format("surface file '{}', mesh '{}': face {} has no corners", file.path,
                                     mesh_name(mesh, m), f));
      }
      types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
               : face.mNumIndices == 2 ? aiPrimitiveType_LINE
               : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                       : aiPrimitiveType_POLYGON;
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices) {
          throw InputError(fmt::format("surface file '{}', mesh '{}': face {} refers to vertex {} of {}", file.path,
                                       mesh_name(mesh, m), f, face.mIndices[k], mesh.mNumVertices));
        }
      }
    }
    mesh.mPrimitiveTypes = types;
  }
}

}  // namespace

std::vector<ImportedMesh> import_meshes(const SurfaceFile& file) {
  // The importer sees the file's own name (its extension picks the reader); any other name it
  // asks for is refused.
  check_reader_guards(file);
  std::string name = std::filesystem::path(file.path).filename().string();
  name = std::filesystem::path(name).stem().string() + file.extension;
  Assimp::Importer importer;
  auto* io = new SingleFileIOSystem(name, file.bytes);
  importer.SetIOHandler(io);  // the importer owns it
  const aiScene* scene = nullptr;
  std::string error;
  try {
    // Read without post-processing, check the indices, then triangulate and join.
    scene = importer.ReadFile(name, 0);
    if (scene != nullptr) {
      check_faces(file, *const_cast<aiScene*>(scene));  // the importer's own scene, not yet post-processed
      scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    }
    if (scene == nullptr) error = importer.GetErrorString();
  } catch (const std::bad_alloc&) {
    throw InputError(fmt::format("surface file '{}': out of memory while reading it", file.path));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    error = e.what();
  }
  // An .obj's material library only colours it: refused, and the geometry is read without it.
  if (!io->refused().empty() && (scene == nullptr || file.extension != ".obj")) {
    throw InputError(fmt::format(
        "surface file '{}' refers to another file '{}': external files are refused; embed the buffers "
        "(a .glb, or data: URIs in a .gltf)",
        file.path, io->refused().front()));
  }
  if (scene == nullptr) {
    throw InputError(fmt::format("surface file '{}' cannot be read as {}: {}", file.path, file.extension,
                                 error.empty() ? "unknown error" : error));
  }
  if (scene->mNumMeshes == 0 || scene->mMeshes == nullptr) {
    throw InputError(fmt::format("surface file '{}' holds no meshes", file.path));
  }
  std::vector<std::vector<Eigen::Matrix4d>> instances(scene->mNumMeshes);
  collect_instances(scene->mRootNode, Eigen::Matrix4d::Identity(), instances, 0);
  std::vector<ImportedMesh> meshes;
  std::map<std::string, std::size_t> by_name;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (scene->mMeshes[m] == nullptr) continue;
    const aiMesh& mesh = *scene->mMeshes[m];
    const std::string mname = mesh_name(mesh, m);
    auto [it, added] = by_name.emplace(mname, meshes.size());
    if (added) meshes.push_back(ImportedMesh{.name = mname, .vertices = Positions(0, 3), .triangles = Triangles(0, 3)});
    ImportedMesh& out = meshes[it->second];
    if (instances[m].empty()) instances[m].push_back(Eigen::Matrix4d::Identity());
    for (const Eigen::Matrix4d& world : instances[m]) append_instance(file, mesh, world, out);
  }
  return meshes;
}

}  // namespace sinew::surface
