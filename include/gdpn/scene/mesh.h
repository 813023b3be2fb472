#pragma once
/// \file
/// Triangle meshes read from files: Assimp for 3ds, obj, stl, gltf/glb, dae and ply; Coin3D
/// for VRML (.wrl) and Inventor (.iv). A file becomes parts, each with its material; the
/// renderer draws them and the physics collides with them. Loaded once per file and shared.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/math.h"

namespace gdpn::scene {

class Node;
class Scene;

/// A material as a mesh file gives it (the fields of a Material node).
struct MeshMaterial {
  std::string name;                        ///< the file's name for it ("" when none)
  std::array<double, 3> ambient{0.2, 0.2, 0.2};   ///< ambient reflectance, 0..1
  std::array<double, 3> diffuse{0.8, 0.8, 0.8};   ///< diffuse colour, 0..1
  std::array<double, 3> specular{0, 0, 0};        ///< specular colour, 0..1
  std::array<double, 3> emissive{0, 0, 0};        ///< emitted colour, 0..1
  double shininess = 0.2;                  ///< 0 dull to 1 mirror-like
  double transparency = 0.0;               ///< 0 opaque to 1 invisible
};

/// One part of a mesh: indexed triangles with normals, in the file's frame (metres).
struct MeshPart {
  std::string name;                ///< the file's name for it
  std::vector<float> positions;    ///< x, y, z per vertex
  std::vector<float> normals;      ///< unit normal per vertex
  std::vector<std::uint32_t> indices;  ///< three per triangle
  int material = -1;               ///< index into MeshData::materials, -1 for none
  /// Triangles in this part.
  [[nodiscard]] std::size_t triangles() const { return indices.size() / 3; }
};

/// What a mesh file holds.
struct MeshData {
  std::string path;                      ///< the file read
  std::vector<MeshPart> parts;           ///< at least one, each with at least one triangle
  std::vector<MeshMaterial> materials;   ///< as the file names them
  /// Triangles over all parts.
  [[nodiscard]] std::size_t triangles() const;
  /// The box around every vertex.
  [[nodiscard]] core::Aabb bounds() const;
};

/// The file extensions gdpn reads meshes from, lower case with the dot.
const std::vector<std::string>& meshExtensions();
/// True when `path` ends in one of meshExtensions() (in any case).
bool isMeshFile(const std::string& path);

/// Reads the mesh at `path` afresh. Only a regular file within core::maxInputBytes() is read;
/// its declared counts must fit its bytes and its nesting stay within 10,000 levels before a
/// library sees it. The library then parses in a child process (core::runInChild) on a 256 MiB
/// stack, within 5 s plus 1 s per MiB and 2 GiB plus 64 times the file's size more than gdpn
/// maps already, so that its
/// crash or hang on a malformed file is a reason here. On failure, null and `why` gives the
/// reason, with the place in the file where there is one.
std::shared_ptr<const MeshData> readMesh(const std::string& path, std::string& why);

/// Reads the mesh at `path` through readMesh (cached: the same file is read once while it is unchanged). On
/// failure, null and `why` gives the importer's reason.
std::shared_ptr<const MeshData> loadMesh(const std::string& path, std::string& why);

/// Builds, under `parent`, a Group named `name` that stands for the mesh at `file` (as the
/// model refers to it; `path` is where it is read): one Material and one Mesh node per part
/// (Mesh.part selects it). Null when the mesh cannot be read or the name is taken; `why`
/// says which.
Node* importMesh(Scene& scene, Node& parent, const std::string& name, const std::string& file,
                 const std::string& path, std::string& why);

}  // namespace gdpn::scene
