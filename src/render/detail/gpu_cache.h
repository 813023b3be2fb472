#pragma once
/// \file
/// GPU copies of what shape nodes load from files (meshes, elevation grids), kept between
/// frames, and why the files that could not be read failed.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/scene/mesh.h"
#include "gdpn/scene/node.h"
#include "gpu_mesh.h"
#include "terrain_gpu.h"

namespace gdpn::render::detail {

/// Meshes and terrains on the GPU, each loaded once; needs a current context for its life.
class GpuCache {
 public:
  /// A mesh file's parts on the GPU.
  struct MeshGpu {
    std::vector<GpuMesh> parts;                  ///< one per part of the file
    std::vector<int> materials;                  ///< each part's material in `data` (-1: none)
    std::shared_ptr<const scene::MeshData> data; ///< the file as read
  };
  /// `model_dir`: where file fields are found.
  explicit GpuCache(std::string model_dir) : dir_(std::move(model_dir)) {}
  ~GpuCache();
  GpuCache(const GpuCache&) = delete;
  GpuCache& operator=(const GpuCache&) = delete;
  /// The mesh of Mesh node `n`; null with `why` when its file cannot be read (tried once:
  /// later asks get the same `why`).
  const MeshGpu* mesh(const scene::Node& n, std::string& why);
  /// The terrain of Terrain node `n` at its size; null with `why` when its file cannot be read
  /// (tried once).
  const TerrainGpu* terrain(const scene::Node& n, std::string& why);

 private:
  std::string dir_;
  std::map<std::string, MeshGpu> meshes_;        // by path
  std::map<std::string, TerrainGpu> terrains_;   // by path and size
  std::map<std::string, std::string> failed_;    // keys that failed, and why
};

}  // namespace gdpn::render::detail
