#include <filesystem>

#include "gdpn/core/text.h"
#include "gdpn/model/model.h"
#include "gdpn/scene/mesh.h"

namespace gdpn::model {

std::optional<Model> meshModel(const std::string& mesh, const std::string& out, core::Diagnostics& diags) {
  namespace fs = std::filesystem;
  const fs::path out_dir = fs::absolute(out).parent_path();
  const std::string relative = fs::relative(fs::absolute(mesh), out_dir).generic_string();
  // a node name from the file name: letters, digits and underscores
  std::string name = fs::path(mesh).stem().string();
  for (auto& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) name = "mesh_" + name;
  auto scene = std::make_shared<scene::Scene>();
  std::string why;
  if (!scene::importMesh(*scene, scene->root(), name, relative, mesh, why)) {
    diags.error({mesh, 0, 0}, "cannot read the mesh file: " + why);
    return std::nullopt;
  }
  Model m;
  m.description = "imported from " + fs::path(mesh).filename().string();
  m.scene = std::move(scene);
  return m;
}

}  // namespace gdpn::model
