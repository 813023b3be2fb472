// Mesh import, one test per format, on small files the tests write: triangle counts and
// materials as the files give them; the subtree an import makes; the reasons for bad files.

#include "gdpn/scene/mesh.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "gdpn/core/file.h"
#include "gdpn/scene/node.h"
#include "support/temp_files.h"

namespace gdpn::scene {
namespace {

namespace fs = std::filesystem;

class MeshImport : public testing::TempDirTest {
 protected:
  std::shared_ptr<const MeshData> load(const std::string& path) {
    std::string why;
    auto mesh = loadMesh(path, why);
    EXPECT_TRUE(mesh) << why;
    return mesh;
  }
};

void expectColour(const std::array<double, 3>& c, double r, double g, double b) {
  EXPECT_NEAR(c[0], r, 1e-3);
  EXPECT_NEAR(c[1], g, 1e-3);
  EXPECT_NEAR(c[2], b, 1e-3);
}

const MeshMaterial& materialOf(const MeshData& m, std::size_t part = 0) {
  static const MeshMaterial none;
  const int i = m.parts.at(part).material;
  return i >= 0 ? m.materials.at(static_cast<std::size_t>(i)) : none;
}

TEST_F(MeshImport, ObjWithItsMaterialLibrary) {
  write("red.mtl", "newmtl red\nKa 0.1 0 0\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 64\nd 0.5\n");
  auto m = load(write("quad.obj", "mtllib red.mtl\no quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl red\nf 1 2 3 4\n"));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 2u);  // the quad is split
  const auto& mat = materialOf(*m);
  expectColour(mat.diffuse, 1, 0, 0);
  expectColour(mat.specular, 0.5, 0.5, 0.5);
  EXPECT_NEAR(mat.transparency, 0.5, 1e-6);
  EXPECT_NEAR(mat.shininess, 0.5, 1e-6);  // Ns 64 of 128
  EXPECT_EQ(m->bounds().hi.x, 1.0);
}

TEST_F(MeshImport, AsciiStl) {
  auto m = load(write("tri.stl",
                      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 0 3 0\nendloop\n"
                      "endfacet\nfacet normal 0 0 1\nouter loop\nvertex 2 0 0\nvertex 2 3 0\nvertex 0 3 0\nendloop\n"
                      "endfacet\nendsolid t\n"));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 2u);
  EXPECT_EQ(m->bounds().hi.y, 3.0);
}

TEST_F(MeshImport, AsciiPly) {
  auto m = load(write("pyramid.ply",
                      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 4u);
}

/// One green triangle as glTF: the JSON, and the binary buffer it points at.
std::string gltfJson(const std::string& uri) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
"materials":[{"name":"green","pbrMetallicRoughness":{"baseColorFactor":[0,1,0,1]}}],
"buffers":[{)" + uri + R"("byteLength":44}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]})";
}

std::string gltfBuffer() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::uint16_t i[4] = {0, 1, 2, 0};
  std::string b(44, '\0');
  std::memcpy(b.data(), p, 36);
  std::memcpy(b.data() + 36, i, 8);
  return b;
}

TEST_F(MeshImport, Gltf) {
  write("tri.bin", gltfBuffer());
  auto m = load(write("tri.gltf", gltfJson(R"("uri":"tri.bin",)")));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 1u);
  expectColour(materialOf(*m).diffuse, 0, 1, 0);
}

TEST_F(MeshImport, Glb) {
  std::string json = gltfJson("");
  while (json.size() % 4 != 0) json += ' ';
  const std::string bin = gltfBuffer();
  auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string glb = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
                          u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
                          u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
  auto m = load(write("tri.glb", glb));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 1u);
  expectColour(materialOf(*m).diffuse, 0, 1, 0);
}

TEST_F(MeshImport, Collada) {
  auto m = load(write("tri.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_effects><effect id="blue-fx"><profile_COMMON><technique sid="c"><phong>
    <diffuse><color>0 0 1 1</color></diffuse></phong></technique></profile_COMMON></effect></library_effects>
  <library_materials><material id="blue" name="blue"><instance_effect url="#blue-fx"/></material></library_materials>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#pa" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="1" material="m"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g">
    <bind_material><technique_common><instance_material symbol="m" target="#blue"/></technique_common></bind_material>
  </instance_geometry></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)"));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 1u);
  expectColour(materialOf(*m).diffuse, 0, 0, 1);
}

/// A 3DS chunk: id, length (header included), body.
std::string chunk(std::uint16_t id, const std::string& body) {
  const auto length = static_cast<std::uint32_t>(6 + body.size());
  return std::string(reinterpret_cast<const char*>(&id), 2) + std::string(reinterpret_cast<const char*>(&length), 4) + body;
}

template <typename T>
std::string raw(T v) {
  return std::string(reinterpret_cast<const char*>(&v), sizeof v);
}

TEST_F(MeshImport, ThreeDs) {
  // one object of two triangles using a material whose diffuse colour is orange
  const std::string colour = chunk(0x0011, std::string("\xff\x80\x00", 3));
  const std::string material = chunk(0xAFFF, chunk(0xA000, std::string("orange\0", 7)) + chunk(0xA020, colour));
  std::string vertices = raw<std::uint16_t>(4);
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) vertices += raw(v);
  std::string faces = raw<std::uint16_t>(2);
  for (int v : {0, 1, 2, 0, 0, 2, 3, 0}) faces += raw(static_cast<std::uint16_t>(v));
  const std::string face_material = chunk(0x4130, std::string("orange\0", 7) + raw<std::uint16_t>(2) + raw<std::uint16_t>(0) +
                                                      raw<std::uint16_t>(1));
  const std::string trimesh = chunk(0x4100, chunk(0x4110, vertices) + chunk(0x4120, faces + face_material));
  const std::string object = chunk(0x4000, std::string("quad\0", 5) + trimesh);
  const std::string file = chunk(0x4D4D, chunk(0x0002, raw<std::uint32_t>(3)) + chunk(0x3D3D, material + object));
  auto m = load(write("quad.3ds", file));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 2u);
  expectColour(materialOf(*m).diffuse, 1.0, 128.0 / 255.0, 0.0);
}

TEST_F(MeshImport, VrmlThroughCoin) {
  auto m = load(write("two.wrl", R"(#VRML V2.0 utf8
Shape {
  appearance Appearance { material Material { diffuseColor 0 0 1 transparency 0.25 } }
  geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } coordIndex [0 1 2 3 -1] }
}
Transform { translation 5 0 0 children Shape {
  appearance Appearance { material Material { diffuseColor 1 0 0 } }
  geometry Box { size 1 1 1 }
} }
)"));
  ASSERT_TRUE(m);
  ASSERT_EQ(m->parts.size(), 2u);
  EXPECT_EQ(m->parts[0].triangles(), 2u);
  EXPECT_EQ(m->parts[1].triangles(), 12u);
  expectColour(materialOf(*m, 0).diffuse, 0, 0, 1);
  EXPECT_NEAR(materialOf(*m, 0).transparency, 0.25, 1e-6);
  expectColour(materialOf(*m, 1).diffuse, 1, 0, 0);
  EXPECT_NEAR(m->bounds().hi.x, 5.5, 1e-6);  // the Transform is applied
}

TEST_F(MeshImport, InventorThroughCoin) {
  auto m = load(write("cube.iv", "#Inventor V2.1 ascii\nSeparator { Material { diffuseColor 1 1 0 } Cube { width 2 } }\n"));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->triangles(), 12u);
  expectColour(materialOf(*m).diffuse, 1, 1, 0);
  EXPECT_NEAR(m->bounds().hi.x, 1.0, 1e-6);
}

TEST_F(MeshImport, AnImportBecomesASubtreeWithItsMaterials) {
  const auto path = write("two.wrl", R"(#VRML V2.0 utf8
Shape { appearance Appearance { material Material { diffuseColor 0 0 1 } } geometry Box {} }
Shape { appearance Appearance { material Material { diffuseColor 0 1 0 } } geometry Sphere {} }
)");
  Scene scene;
  std::string why;
  Node* group = importMesh(scene, scene.root(), "part", "two.wrl", path, why);
  ASSERT_TRUE(group) << why;
  ASSERT_EQ(group->children().size(), 4u);
  EXPECT_EQ(group->children()[0]->type().name, "Material");
  const auto d = group->children()[2]->vec3(field::Material::Diffuse);
  EXPECT_EQ(d, (core::Vec3{0, 1, 0}));
  EXPECT_EQ(group->children()[3]->type().name, "Mesh");
  EXPECT_EQ(group->children()[3]->text(field::Mesh::File), "two.wrl");
  EXPECT_EQ(group->children()[3]->number(field::Mesh::Part), 1.0);
  EXPECT_FALSE(importMesh(scene, scene.root(), "part", "two.wrl", path, why));
  EXPECT_EQ(why, "the name 'part' is taken");
}

TEST_F(MeshImport, BadFilesGiveTheImportersReason) {
  std::string why;
  EXPECT_FALSE(loadMesh((dir_ / "none.obj").string(), why));
  EXPECT_EQ(why, "no such file");
  EXPECT_FALSE(loadMesh(write("x.xyz", "1 2 3\n"), why));
  EXPECT_EQ(why, "unsupported mesh format '.xyz' (gdpn reads obj, stl, 3ds, gltf, glb, dae, ply, wrl, iv)");
  EXPECT_FALSE(loadMesh(write("bad.iv", "#Inventor V2.1 ascii\nSeparator { Cube { width } }\n"), why));
  EXPECT_NE(why.find("Coin read error"), std::string::npos) << why;
  EXPECT_FALSE(loadMesh(write("empty.obj", "# nothing\n"), why));
  EXPECT_FALSE(why.empty());
  EXPECT_FALSE(loadMesh(write("bad.gltf", "{\"asset\": "), why));
  EXPECT_FALSE(why.empty());
}

TEST(MeshSeeds, EveryFormatReadsOneTriangle) {
  // the fuzzer's seeds: one triangle in each format gdpn reads
  int files = 0;
  for (const auto& e : fs::directory_iterator(fs::path(GDPN_SOURCE_DIR) / "tests/data/meshes")) {
    std::string why;
    auto m = readMesh(e.path().string(), why);
    ASSERT_TRUE(m) << e.path() << ": " << why;
    EXPECT_EQ(m->triangles(), 1u) << e.path();
    ++files;
  }
  EXPECT_EQ(files, 11);
}

// --- hostile files: each is refused with the place in the file, quickly, without a crash ---

/// Loads `path`, expecting a refusal within a few seconds; returns the reason.
std::string refusal(const std::string& path) {
  std::string why;
  EXPECT_LT(testing::secondsFor([&] { EXPECT_FALSE(loadMesh(path, why)) << path; }), 5.0) << path;
  return why;
}

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

TEST_F(MeshImport, DeepNestingIsRefusedWhereItGoesTooDeep) {
  // VRML: two levels per Group (its braces and its children's brackets); the 10001st bracket
  // is the 5001st group's '{', at column 15 * 5000 + 6 of line 2
  const std::string group = "Group{children[";  // 15 characters
  EXPECT_EQ(refusal(write("deep.wrl", "#VRML V2.0 utf8\n" + repeat(group, 200000) + "\n")),
            "line 2 column " + std::to_string(15 * 5000 + 6) + ": nested more than 10000 levels deep, the most gdpn reads");
  EXPECT_EQ(refusal(write("deep.iv", "#Inventor V2.1 ascii\n" + repeat("Separator { ", 100000))),
            "line 2 column " + std::to_string(12 * 10000 + 11) + ": nested more than 10000 levels deep, the most gdpn reads");
  EXPECT_EQ(refusal(write("deep.dae", "<?xml version=\"1.0\"?>\n<COLLADA>\n" + repeat("<node>", 100000))),
            "line 3 column " + std::to_string(6 * 9999 + 1) + ": nested more than 10000 levels deep, the most gdpn reads");
  EXPECT_EQ(refusal(write("deep.gltf", "{\"asset\":" + repeat("[", 100000))),
            "line 1 column " + std::to_string(10 + 9999) + ": nested more than 10000 levels deep, the most gdpn reads");
  // brackets inside strings and comments do not count
  EXPECT_NE(refusal(write("strings.wrl", "#VRML V2.0 utf8\n# " + repeat("[", 20000) + "\nWorldInfo { title \"" +
                                             repeat("{", 20000) + "\" }\n")),
            std::string("nested"));
}

TEST_F(MeshImport, DeepButLegalNestingReads) {
  // deeper than a default thread's stack carries Coin and Assimp: read on a stack of our own
  auto wrl = load(write("deep.wrl", "#VRML V2.0 utf8\n" + repeat("Group { children [ ", 4990) +
                                        "Shape { geometry Box {} }" + repeat(" ] }", 4990) + "\n"));
  ASSERT_TRUE(wrl);
  EXPECT_EQ(wrl->triangles(), 12u);
  auto iv = load(write("deep.iv", "#Inventor V2.1 ascii\n" + repeat("Separator { ", 9990) + "Cube {}" + repeat("}", 9990)));
  ASSERT_TRUE(iv);
  EXPECT_EQ(iv->triangles(), 12u);
}

TEST_F(MeshImport, DeclaredCountsMustFitTheBytesPresent) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(refusal(write("huge.ply", header + "0 0 0\n")),
            "line 3 column 1: element 'vertex' declares 2000000000 items, more than the 6 bytes after the header can hold");
  std::string binary = header;
  binary.replace(binary.find("ascii"), 5, "binary_little_endian");
  EXPECT_EQ(refusal(write("hugeb.ply", binary + std::string(20, '\0'))),
            "line 3 column 1: element 'vertex' declares 2000000000 items, more than the 20 bytes after the header can hold");
  // a face whose index list claims four billion entries
  const std::string one = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                          "element face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(refusal(write("list.ply", one + "4000000000 0 1 2\n")),
            "line 13 column 1: a list of element 'face' declares 4000000000 entries, more than the rest of the file holds");
  std::string listb = "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  const auto at = listb.size();
  listb += std::string("\xff\xff\xff\x7f", 4) + std::string(12, '\0');
  EXPECT_EQ(refusal(write("listb.ply", listb)), "byte " + std::to_string(at) +
                                                    ": a list of element 'face' declares 2147483647 entries, more than the rest of the file holds");
  // a header whose end_header is not a line of its own (Assimp hung on it)
  EXPECT_EQ(refusal(write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\nx\x05end_header\n")),
            "the PLY header has no 'end_header' line of its own within its first MiB");
  // a property of no PLY type (Assimp aborted on it; found by the mesh fuzzer)
  EXPECT_EQ(refusal(write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty \xff\xff x\nend_header\n0\n")),
            "line 4 column 1: a header line or property type PLY does not have");
  EXPECT_EQ(refusal(write("line.ply", "ply\nformat ascii 1.0\nelement vertex 1\npro\xbb" "erty float x\nend_header\n0\n")),
            "line 4 column 1: a header line or property type PLY does not have");
  // a binary STL claiming two billion triangles, a glb whose header claims a gigabyte
  std::string stl(80, '\0');
  stl += std::string("\x00\x94\x35\x77", 4) + std::string(50, '\0');
  EXPECT_NE(refusal(write("huge.stl", stl)).find("STL"), std::string::npos);
  std::string glb = "glTF";
  glb += std::string("\x02\0\0\0\x00\xca\x9a\x3b\x00\x94\x35\x77", 12) + "JSON{";
  EXPECT_EQ(refusal(write("huge.glb", glb)), "its header declares 2000000000 bytes, but the file holds 21");
}

TEST_F(MeshImport, OnlyRegularFilesWithinTheLimitAreRead) {
  EXPECT_EQ(refusal("/dev/zero"), "is a character device, not a regular file");
  const auto fifo = (dir_ / "pipe.obj").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refusal(fifo), "is a FIFO, not a regular file");  // no writer: it must not wait for one
  // a gigabyte of nothing, sparse on disk
  const auto big = write("big.obj", "");
  fs::resize_file(big, std::uintmax_t{1} << 30);
  EXPECT_EQ(refusal(big), "the file is 1024 MiB; gdpn reads input files of at most 256 MiB");
  // garbage over a lowered limit
  core::InputLimit limit(4096);
  EXPECT_EQ(refusal(write("garbage.dae", std::string(5000, '<'))), "the file is 5000 bytes; gdpn reads input files of at most 4 KiB");
}

}  // namespace
}  // namespace gdpn::scene
