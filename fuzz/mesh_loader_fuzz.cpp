// libFuzzer target: any bytes as a mesh file must give a mesh or a reason, never a crash, a
// hang, unbounded memory or a sanitizer report. The bytes' opening picks the format (as the
// seeds have it), so that mutations reach every importer: Assimp's and Coin3D's.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include "gdpn/core/file.h"
#include "gdpn/scene/mesh.h"

namespace {

/// The extension the file is given, from how it opens.
const char* extensionFor(std::string_view bytes) {
  struct Magic {
    std::string_view start;
    const char* ext;
  };
  static constexpr Magic kMagic[] = {{"ply", ".ply"},        {"solid", ".stl"},   {"glTF", ".glb"},
                                     {"{", ".gltf"},         {"<", ".dae"},       {"#VRML", ".wrl"},
                                     {"#Inventor", ".iv"},   {"MM", ".3ds"}};
  for (const auto& m : kMagic) {
    if (bytes.starts_with(m.start)) return m.ext;
  }
  // no magic: binary STL (a header of 80 bytes) or OBJ text
  return bytes.size() >= 84 && bytes.size() % 2 == 0 ? ".stl" : ".obj";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  static const std::string stem = "/tmp/gdpn_mesh_fuzz_" + std::to_string(::getpid());
  const std::string path = stem + extensionFor(bytes);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(size));
  // a low limit, so that the size check is reached too
  static gdpn::core::InputLimit limit(48 * 1024);
  std::string why;
  const auto mesh = gdpn::scene::readMesh(path, why);
  // a mesh has triangles whose indices name its vertices; a failure has a reason
  if (!mesh && why.empty()) __builtin_trap();
  if (mesh) {
    for (const auto& part : mesh->parts) {
      for (const auto i : part.indices) {
        if (std::size_t{i} * 3 >= part.positions.size()) __builtin_trap();
      }
    }
  }
  ::unlink(path.c_str());
  return 0;
}
