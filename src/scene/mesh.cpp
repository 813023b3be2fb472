#include "gdpn/scene/mesh.h"

#include <Inventor/SbLinear.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShape.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>

#include "gdpn/scene/node.h"

namespace gdpn::scene {

std::size_t MeshData::triangles() const {
  std::size_t n = 0;
  for (const auto& p : parts) n += p.triangles();
  return n;
}

core::Aabb MeshData::bounds() const {
  core::Aabb box;
  for (const auto& p : parts) {
    for (std::size_t i = 0; i + 2 < p.positions.size(); i += 3) box.add(core::Vec3{p.positions[i], p.positions[i + 1], p.positions[i + 2]});
  }
  return box;
}

const std::vector<std::string>& meshExtensions() {
  static const std::vector<std::string> kExt = {".obj", ".stl", ".3ds", ".gltf", ".glb", ".dae", ".ply", ".wrl", ".iv"};
  return kExt;
}

namespace {

/// The file's extension in lower case, with the dot.
std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

bool isMeshFile(const std::string& path) {
  const std::string ext = extensionOf(path);
  const auto& known = meshExtensions();
  return std::find(known.begin(), known.end(), ext) != known.end();
}

namespace {

/// Adds the part only when it has triangles.
void keep(MeshData& mesh, MeshPart part) {
  if (part.indices.empty()) return;
  if (part.normals.size() != part.positions.size()) part.normals.assign(part.positions.size(), 0.0f);
  mesh.parts.push_back(std::move(part));
}

// --- Assimp ------------------------------------------------------------------------------

std::array<double, 3> color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                            std::array<double, 3> fallback) {
  aiColor3D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return fallback;
  return {std::clamp<double>(c.r, 0, 1), std::clamp<double>(c.g, 0, 1), std::clamp<double>(c.b, 0, 1)};
}

bool readWithAssimp(const std::string& path, MeshData& mesh, std::string& why) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* s = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                 aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices |
                                                 aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (s == nullptr || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || s->mRootNode == nullptr) {
    why = importer.GetErrorString();
    if (why.empty()) why = "the importer found no scene in it";
    return false;
  }
  for (unsigned i = 0; i < s->mNumMaterials; ++i) {
    const aiMaterial& m = *s->mMaterials[i];
    MeshMaterial out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    out.ambient = color(m, AI_MATKEY_COLOR_AMBIENT, out.ambient);
    out.diffuse = color(m, AI_MATKEY_COLOR_DIFFUSE, out.diffuse);
    out.specular = color(m, AI_MATKEY_COLOR_SPECULAR, out.specular);
    out.emissive = color(m, AI_MATKEY_COLOR_EMISSIVE, out.emissive);
    float shininess = 0, opacity = 1;
    // exponents run to 128 in most formats (Inventor's shininess 1 is 128)
    if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS) out.shininess = std::clamp(static_cast<double>(shininess) / 128.0, 0.0, 1.0);
    if (m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) out.transparency = std::clamp(1.0 - static_cast<double>(opacity), 0.0, 1.0);
    mesh.materials.push_back(out);
  }
  for (unsigned i = 0; i < s->mNumMeshes; ++i) {
    const aiMesh& m = *s->mMeshes[i];
    if ((m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    MeshPart part;
    part.name = m.mName.C_Str();
    part.material = static_cast<int>(m.mMaterialIndex);
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      part.positions.insert(part.positions.end(), {m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z});
      if (m.mNormals != nullptr) {
        part.normals.insert(part.normals.end(), {m.mNormals[v].x, m.mNormals[v].y, m.mNormals[v].z});
      }
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) continue;
      part.indices.insert(part.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    keep(mesh, std::move(part));
  }
  return true;
}

// --- Coin3D ------------------------------------------------------------------------------

struct CoinRead {
  MeshData* mesh = nullptr;
  MeshPart part;
  std::string errors;
};

CoinRead* g_coin = nullptr;  // the read in progress (Coin's error handlers take no context we own)

void coinError(const SoError* error, void*) {
  if (g_coin == nullptr) return;
  if (!g_coin->errors.empty()) g_coin->errors += "; ";
  std::string raw = error->getDebugString().getString(), text;
  // one line: Coin breaks its messages with newlines and tabs
  for (char c : raw) {
    if (c == '\n' || c == '\t') {
      if (!text.empty() && text.back() != ' ') text += ' ';
    } else {
      text += c;
    }
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  g_coin->errors += text;
}

SoCallbackAction::Response coinShape(void* data, SoCallbackAction* action, const SoNode*) {
  auto* read = static_cast<CoinRead*>(data);
  keep(*read->mesh, std::move(read->part));
  read->part = {};
  SbColor ambient, diffuse, specular, emission;
  float shininess = 0, transparency = 0;
  action->getMaterial(ambient, diffuse, specular, emission, shininess, transparency);
  MeshMaterial m;
  m.ambient = {ambient[0], ambient[1], ambient[2]};
  m.diffuse = {diffuse[0], diffuse[1], diffuse[2]};
  m.specular = {specular[0], specular[1], specular[2]};
  m.emissive = {emission[0], emission[1], emission[2]};
  m.shininess = shininess;
  m.transparency = transparency;
  read->mesh->materials.push_back(m);
  read->part.material = static_cast<int>(read->mesh->materials.size() - 1);
  return SoCallbackAction::CONTINUE;
}

void coinTriangle(void* data, SoCallbackAction* action, const SoPrimitiveVertex* a, const SoPrimitiveVertex* b,
                  const SoPrimitiveVertex* c) {
  auto* read = static_cast<CoinRead*>(data);
  const SbMatrix& model = action->getModelMatrix();
  for (const SoPrimitiveVertex* v : {a, b, c}) {
    SbVec3f p, n;
    model.multVecMatrix(v->getPoint(), p);
    model.multDirMatrix(v->getNormal(), n);
    n.normalize();
    read->part.indices.push_back(static_cast<std::uint32_t>(read->part.positions.size() / 3));
    read->part.positions.insert(read->part.positions.end(), {p[0], p[1], p[2]});
    read->part.normals.insert(read->part.normals.end(), {n[0], n[1], n[2]});
  }
}

bool readWithCoin(const std::string& path, MeshData& mesh, std::string& why) {
  static std::once_flag once;
  std::call_once(once, [] {
    SoDB::init();
    SoReadError::setHandlerCallback(coinError, nullptr);
    SoDebugError::setHandlerCallback(coinError, nullptr);
  });
  CoinRead read;
  read.mesh = &mesh;
  g_coin = &read;
  SoInput in;
  SoSeparator* root = nullptr;
  if (in.openFile(path.c_str())) root = SoDB::readAll(&in);
  if (root == nullptr) {
    g_coin = nullptr;
    why = read.errors.empty() ? "not a VRML or Inventor file" : read.errors;
    return false;
  }
  root->ref();
  SoCallbackAction action;
  action.addPreCallback(SoShape::getClassTypeId(), coinShape, &read);
  action.addTriangleCallback(SoShape::getClassTypeId(), coinTriangle, &read);
  action.apply(root);
  keep(mesh, std::move(read.part));
  root->unref();
  g_coin = nullptr;
  return true;
}

}  // namespace

std::shared_ptr<const MeshData> loadMesh(const std::string& path, std::string& why) {
  namespace fs = std::filesystem;
  static std::mutex mutex;
  struct Entry {
    fs::file_time_type time;
    std::uintmax_t size = 0;
    std::shared_ptr<const MeshData> mesh;
  };
  static std::map<std::string, Entry> cache;

  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    why = "no such file";
    return nullptr;
  }
  const std::string ext = extensionOf(path);
  if (!isMeshFile(path)) {
    why = "unsupported mesh format '" + ext + "' (gdpn reads obj, stl, 3ds, gltf, glb, dae, ply, wrl, iv)";
    return nullptr;
  }
  const bool coin = ext == ".wrl" || ext == ".iv";
  const auto time = fs::last_write_time(path, ec);
  const auto size = fs::file_size(path, ec);
  std::lock_guard lock(mutex);
  if (auto it = cache.find(path); it != cache.end() && it->second.time == time && it->second.size == size) {
    return it->second.mesh;
  }
  auto mesh = std::make_shared<MeshData>();
  mesh->path = path;
  const bool ok = coin ? readWithCoin(path, *mesh, why) : readWithAssimp(path, *mesh, why);
  if (!ok) return nullptr;
  if (mesh->parts.empty()) {
    why = "it holds no triangles";
    return nullptr;
  }
  for (const auto& part : mesh->parts) {
    for (float x : part.positions) {
      if (!std::isfinite(x)) {
        why = "it holds a vertex that is not a finite number";
        return nullptr;
      }
    }
  }
  cache[path] = {time, size, mesh};
  return mesh;
}

Node* importMesh(Scene& scene, Node& parent, const std::string& name, const std::string& file, const std::string& path,
                 std::string& why) {
  auto mesh = loadMesh(path, why);
  if (!mesh) return nullptr;
  const auto& types = scene.types();
  Node* group = scene.create(*types.find(NodeKind::Group), name, parent);
  if (group == nullptr) {
    why = "the name '" + name + "' is taken";
    return nullptr;
  }
  const NodeType& material_type = *types.find(NodeKind::Material);
  const NodeType& mesh_type = *types.find(NodeKind::Mesh);
  for (std::size_t i = 0; i < mesh->parts.size(); ++i) {
    const auto& part = mesh->parts[i];
    if (part.material >= 0 && static_cast<std::size_t>(part.material) < mesh->materials.size()) {
      const MeshMaterial& m = mesh->materials[static_cast<std::size_t>(part.material)];
      Node* look = scene.create(material_type, "material" + std::to_string(i), *group);
      look->setValue(field::Material::Ambient, m.ambient);
      look->setValue(field::Material::Diffuse, m.diffuse);
      look->setValue(field::Material::Specular, m.specular);
      look->setValue(field::Material::Emissive, m.emissive);
      look->setValue(field::Material::Shininess, m.shininess);
      look->setValue(field::Material::Transparency, m.transparency);
    }
    Node* shape = scene.create(mesh_type, "part" + std::to_string(i), *group);
    shape->setValue(field::Mesh::File, file);
    shape->setValue(field::Mesh::Part, static_cast<std::int64_t>(i));
  }
  return group;
}

}  // namespace gdpn::scene
