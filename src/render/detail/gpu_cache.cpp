#include "gpu_cache.h"

#include <filesystem>
#include <utility>

#include "gdpn/scene/terrain.h"

namespace gdpn::render::detail {

namespace field = scene::field;

GpuCache::~GpuCache() {
  for (auto& [k, m] : meshes_) {
    for (auto& p : m.parts) p.release();
  }
  for (auto& [k, t] : terrains_) t.release();
}

const GpuCache::MeshGpu* GpuCache::mesh(const scene::Node& n, std::string& why) {
  const std::string file = n.text(field::Mesh::File);
  const std::string path = (std::filesystem::path(dir_) / file).string();
  if (auto it = meshes_.find(path); it != meshes_.end()) return &it->second;
  if (auto it = failed_.find(path); it != failed_.end()) {
    why = it->second;
    return nullptr;
  }
  std::string reason;
  auto data = file.empty() ? nullptr : scene::loadMesh(path, reason);
  if (!data) {
    why = failed_[path] = "cannot read the mesh file '" + file + "': " + (file.empty() ? "none is named" : reason);
    return nullptr;
  }
  MeshGpu m;
  m.data = data;
  for (const auto& part : data->parts) {
    std::vector<float> v;
    for (std::size_t k = 0; k + 2 < part.positions.size(); k += 3) {
      v.insert(v.end(), {part.positions[k], part.positions[k + 1], part.positions[k + 2], part.normals[k],
                         part.normals[k + 1], part.normals[k + 2]});
    }
    GpuMesh g;
    g.upload(v, part.indices);
    m.parts.push_back(g);
    m.materials.push_back(part.material);
  }
  return &(meshes_[path] = std::move(m));
}

const TerrainGpu* GpuCache::terrain(const scene::Node& n, std::string& why) {
  const std::string file = n.text(field::Terrain::File);
  const std::string path = (std::filesystem::path(dir_) / file).string();
  const double width = n.number(field::Terrain::Width), depth = n.number(field::Terrain::Depth),
               height_scale = n.number(field::Terrain::HeightScale);
  const std::string key =
      path + "|" + std::to_string(width) + "|" + std::to_string(depth) + "|" + std::to_string(height_scale);
  if (auto it = terrains_.find(key); it != terrains_.end()) return &it->second;
  if (auto it = failed_.find(key); it != failed_.end()) {
    why = it->second;
    return nullptr;
  }
  std::string reason;
  auto grid = scene::loadHeightGrid(path, reason);
  TerrainGpu t;
  if (!grid || !t.build(*grid, width, depth, height_scale)) {
    why = failed_[key] = "cannot read the elevation file '" + file + "': " + (grid ? "too few samples" : reason);
    return nullptr;
  }
  return &(terrains_[key] = t);
}

}  // namespace gdpn::render::detail
