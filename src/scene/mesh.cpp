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

#include <pthread.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>

#include "gdpn/core/child_process.h"
#include "gdpn/core/file.h"
#include "gdpn/core/text.h"
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
    for (std::size_t i = 0; i + 2 < p.positions.size(); i += 3) {
      box.add(core::Vec3{static_cast<double>(p.positions[i]), static_cast<double>(p.positions[i + 1]),
                         static_cast<double>(p.positions[i + 2])});
    }
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

// --- checks before a library sees the file -------------------------------------------------

/// Deepest nesting of groups (VRML/Inventor braces, COLLADA elements, glTF JSON) gdpn hands a
/// library: deeper files are refused before parsing, as the libraries recurse once per level.
constexpr int kMaxNesting = 10000;
/// The stack the libraries parse on: deep but legal files recurse far.
constexpr std::size_t kParseStackBytes = std::size_t{256} << 20;

/// "line L column C" of byte `at` in `text`.
std::string placeIn(const std::string& text, std::size_t at) {
  const auto [line, column] = core::lineColumn(text, at);
  return "line " + std::to_string(line) + " column " + std::to_string(column);
}

/// Where a COLLADA file's numbers that Assimp trusts are wrong, or npos: a `count`, `stride`,
/// `offset` or `set` attribute that is not a whole number below a billion, or an array
/// (`float_array`, `int_array`, ...) holding another number of values than its `count` says,
/// or an index list (`p`, `v`, `vcount`) holding anything but whole numbers below a billion.
/// Assimp sizes its buffers by these and then reads past them. `what` says which.
std::size_t badColladaNumber(std::string_view text, std::string& what) {
  for (std::size_t at = text.find('='); at != std::string_view::npos; at = text.find('=', at + 1)) {
    std::size_t name_end = at;
    while (name_end > 0 && text[name_end - 1] == ' ') --name_end;
    std::size_t name_begin = name_end;
    while (name_begin > 0 && (std::isalnum(static_cast<unsigned char>(text[name_begin - 1])) != 0 ||
                              text[name_begin - 1] == '_')) {
      --name_begin;
    }
    const auto name = text.substr(name_begin, name_end - name_begin);
    if (name != "count" && name != "stride" && name != "offset" && name != "set") continue;
    std::size_t v = at + 1;
    while (v < text.size() && text[v] == ' ') ++v;
    if (v >= text.size() || (text[v] != '"' && text[v] != '\'')) continue;
    const auto close = text.find(text[v], v + 1);
    if (close == std::string_view::npos) continue;
    const auto value = text.substr(v + 1, close - v - 1);
    const bool whole = !value.empty() && value.size() <= 9 &&
                       std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!whole) {
      what = "its " + std::string(name) + " is not a whole number below a billion";
      return v;
    }
    // an array's values must be as many as its count: <float_array ... count="N">v v v</float_array>
    if (name != "count") continue;
    const auto open = text.rfind('<', name_begin);
    if (open == std::string_view::npos) continue;
    const auto element = text.substr(open + 1, text.find_first_of(" \t\r\n>", open + 1) - open - 1);
    if (!element.ends_with("_array")) continue;
    const auto body = text.find('>', close);
    const auto end = body == std::string_view::npos ? body : text.find('<', body);
    if (end == std::string_view::npos) continue;
    std::size_t values = 0;
    bool in_value = false;
    for (std::size_t i = body + 1; i < end; ++i) {
      const bool space = text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n';
      if (!space && !in_value) ++values;
      in_value = !space;
    }
    if (values != std::stoull(std::string(value))) {
      what = "its " + std::string(element) + " says " + std::string(value) + " values but holds " + std::to_string(values);
      return v;
    }
  }
  // index lists: <p>, <v> and <vcount> hold whole numbers only
  for (const std::string_view tag : {"<p", "<v", "<vcount"}) {
    for (std::size_t at = text.find(tag); at != std::string_view::npos; at = text.find(tag, at + 1)) {
      const std::size_t after = at + tag.size();
      if (after >= text.size() || (text[after] != '>' && text[after] != ' ')) continue;
      const auto body = text.find('>', after);
      const auto end = body == std::string_view::npos ? body : text.find('<', body);
      if (end == std::string_view::npos) continue;
      std::size_t digits = 0;
      for (std::size_t i = body + 1; i < end; ++i) {
        const char c = text[i];
        const bool space = c == ' ' || c == '\t' || c == '\r' || c == '\n';
        digits = space ? 0 : digits + 1;
        if ((!space && (c < '0' || c > '9')) || digits > 9) {
          what = "its <" + std::string(tag.substr(1)) + "> holds something other than whole numbers below a billion";
          return i - digits + 1;
        }
      }
    }
  }
  return std::string_view::npos;
}

/// Where `text` first nests deeper than kMaxNesting, or npos. Brackets (`{[` for VRML, Inventor
/// and JSON) or XML elements (`xml`) open a level; strings and comments are skipped.
std::size_t tooDeep(std::string_view text, bool xml) {
  int depth = 0;
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (xml) {
      if (c != '<' || i + 1 >= n) continue;
      const char next = text[i + 1];
      if (next == '/') {
        --depth;
      } else if (next == '!' || next == '?') {
        // comments, declarations and CDATA open nothing; skip a comment whole
        if (text.substr(i, 4) == "<!--") {
          const auto end = text.find("-->", i + 4);
          i = end == std::string::npos ? n : end + 2;
        }
      } else {
        const auto end = text.find('>', i);
        if (end == std::string::npos) break;
        if (text[end - 1] != '/' && ++depth > kMaxNesting) return i;
        i = end;
      }
    } else if (c == '"') {
      // a string, with backslash escapes
      for (++i; i < n && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
      }
    } else if (c == '#') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxNesting) return i;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return std::string::npos;
}

/// Bytes one value of a PLY scalar type takes in binary ("float" 4), 0 when unknown.
std::size_t plyTypeBytes(const std::string& type) {
  static const std::map<std::string, std::size_t> kBytes = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},   {"uint8", 1},   {"short", 2},   {"ushort", 2},  {"int16", 2},
      {"uint16", 2}, {"int", 4},   {"uint", 4},   {"int32", 4},   {"uint32", 4},  {"float", 4},   {"float32", 4},
      {"double", 8}, {"float64", 8}};
  const auto it = kBytes.find(type);
  return it == kBytes.end() ? 0 : it->second;
}

/// A PLY file's layout as its header gives it.
struct PlyLayout {
  struct Property {
    std::size_t bytes = 0;        // of a scalar, or of each list entry (binary; 0 when unknown)
    std::size_t count_bytes = 0;  // of a list's count (binary), 0 for a scalar
    bool list = false;
  };
  struct Element {
    std::string name;
    std::uintmax_t count = 0;
    std::size_t at = 0;  // where the header declares it
    std::vector<Property> properties;
  };
  std::vector<Element> elements;
  enum class Format { Ascii, Little, Big } format = Format::Ascii;
  std::size_t body = std::string::npos;  // where the data begin, npos without end_header
  std::size_t bad_type = std::string::npos;  // the first header line or property type PLY lacks
};

PlyLayout plyLayout(const std::string& text) {
  PlyLayout ply;
  std::size_t pos = 0;
  // a header is short: look no further than its first MiB
  while (pos < std::min<std::size_t>(text.size(), std::size_t{1} << 20)) {
    auto end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::istringstream line(text.substr(pos, end - pos));
    std::string word;
    line >> word;
    if (word == "format") {
      line >> word;
      ply.format = word == "binary_little_endian" ? PlyLayout::Format::Little
                   : word == "binary_big_endian"  ? PlyLayout::Format::Big
                                                  : PlyLayout::Format::Ascii;
    } else if (word == "element") {
      PlyLayout::Element e;
      e.at = pos;
      line >> e.name >> e.count;
      ply.elements.push_back(e);
    } else if (word == "property" && !ply.elements.empty()) {
      PlyLayout::Property p;
      std::string type;
      line >> type;
      if (type == "list") {
        std::string count_type;
        line >> count_type >> type;
        p.list = true;
        p.count_bytes = plyTypeBytes(count_type);
      }
      p.bytes = plyTypeBytes(type);
      if (p.bytes == 0 || (p.list && p.count_bytes == 0)) ply.bad_type = std::min(ply.bad_type, pos);
      ply.elements.back().properties.push_back(p);
    } else if (word == "end_header") {
      ply.body = end + 1;
      break;
    } else if (word != "ply" && word != "comment" && word != "obj_info" && !word.empty()) {
      ply.bad_type = std::min(ply.bad_type, pos);  // a line PLY does not have
    }
    pos = end + 1;
  }
  return ply;
}

/// True when the data of a PLY file hold what its header and its list counts declare: a count
/// of two billion with a few bytes of data is refused before the importer allocates for it.
/// Walks the data once without keeping them.
bool plyCountsFit(const std::string& text, std::string& why) {
  const PlyLayout ply = plyLayout(text);
  // without its end_header line Assimp's reader searches for ever
  if (ply.body == std::string::npos || ply.body > text.size()) {
    why = "the PLY header has no 'end_header' line of its own within its first MiB";
    return false;
  }
  // Assimp aborts in its post-processing on some properties of no known type
  if (ply.bad_type != std::string::npos) {
    why = placeIn(text, ply.bad_type) + ": a header line or property type PLY does not have";
    return false;
  }
  const bool ascii = ply.format == PlyLayout::Format::Ascii;
  const std::size_t have = text.size() - ply.body;
  // each element first: it takes at least a byte per property (two as text)
  std::uintmax_t least = 0;
  for (const auto& e : ply.elements) {
    const std::uintmax_t item = std::max<std::uintmax_t>(1, e.properties.size() * (ascii ? 2 : 1));
    if (e.count > have / item || least + e.count * item > have) {
      why = placeIn(text, e.at) + ": element '" + e.name + "' declares " + std::to_string(e.count) +
            " items, more than the " + std::to_string(have) + " bytes after the header can hold";
      return false;
    }
    least += e.count * item;
  }
  // then every list: its count must fit in what is left
  std::size_t pos = ply.body;
  auto skipSpace = [&] {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
  };
  auto listTooLong = [&](std::size_t at, std::uintmax_t count, const PlyLayout::Element& e) {
    why = (ascii ? placeIn(text, at) : "byte " + std::to_string(at)) + ": a list of element '" + e.name +
          "' declares " + std::to_string(count) + " entries, more than the rest of the file holds";
    return false;
  };
  for (const auto& e : ply.elements) {
    for (std::uintmax_t i = 0; i < e.count; ++i) {
      for (const auto& p : e.properties) {
        if (ascii) {
          skipSpace();
          const std::size_t at = pos;
          while (pos < text.size() && !std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
          if (!p.list) continue;
          const std::uintmax_t count = std::strtoull(text.substr(at, pos - at).c_str(), nullptr, 10);
          if (count > (text.size() - pos) / 2) return listTooLong(at, count, e);
          for (std::uintmax_t k = 0; k < count; ++k) {
            skipSpace();
            while (pos < text.size() && !std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
          }
          continue;
        }
        if (p.bytes == 0 || (p.list && p.count_bytes == 0)) return true;  // an unknown type: the importer says
        if (!p.list) {
          pos += p.bytes;
          continue;
        }
        if (text.size() - std::min(pos, text.size()) < p.count_bytes) return true;  // truncated: the importer says
        std::uintmax_t count = 0;
        for (std::size_t k = 0; k < p.count_bytes; ++k) {
          const std::size_t byte = ply.format == PlyLayout::Format::Little ? p.count_bytes - 1 - k : k;
          count = (count << 8) | static_cast<unsigned char>(text[pos + byte]);
        }
        const std::size_t at = pos;
        pos += p.count_bytes;
        if (count > (text.size() - pos) / p.bytes) return listTooLong(at, count, e);
        pos += static_cast<std::size_t>(count) * p.bytes;
      }
      if (pos > text.size()) return true;  // truncated: the importer says
    }
  }
  return true;
}

/// Checks what the file declares against what it holds, before any library reads it: a size
/// within core::maxInputBytes(), nesting within kMaxNesting, PLY counts within the bytes.
bool precheck(const std::string& path, const std::string& ext, std::string& why) {
  core::Diagnostics diags;
  auto text = core::readFile(path, diags);
  if (!text) {
    why = diags.all().empty() ? "cannot read the file" : diags.all().front().message;
    return false;
  }
  if (ext == ".ply") return plyCountsFit(*text, why);
  // a glb holds its JSON in the first chunk, after a 12-byte header and an 8-byte chunk header
  std::string_view scan = *text;
  if (ext == ".glb") {
    // the header's total length and the chunk's must lie within the file
    std::uint32_t total = 0, length = 0;
    if (text->size() >= 20) {
      std::memcpy(&total, text->data() + 8, sizeof total);
      std::memcpy(&length, text->data() + 12, sizeof length);
    }
    if (text->size() < 20 || total > text->size() || length > text->size() - 20) {
      why = "its header declares " + std::to_string(std::max(total, length)) + " bytes, but the file holds " +
            std::to_string(text->size());
      return false;
    }
    scan = scan.substr(20, length);
  }
  const bool text_form = ext == ".wrl" || ext == ".gltf" || ext == ".glb" || ext == ".dae" ||
                         (ext == ".iv" && text->find("binary") > text->find('\n'));
  if (!text_form) return true;
  if (const auto at = tooDeep(scan, ext == ".dae"); at != std::string::npos) {
    why = placeIn(*text, at + static_cast<std::size_t>(scan.data() - text->data())) + ": nested more than " +
          std::to_string(kMaxNesting) + " levels deep, the most gdpn reads";
    return false;
  }
  if (ext == ".dae") {
    std::string what;
    if (const auto at = badColladaNumber(scan, what); at != std::string::npos) {
      why = placeIn(*text, at + static_cast<std::size_t>(scan.data() - text->data())) + ": " + what;
      return false;
    }
  }
  return true;
}

/// Runs `work` on a thread of its own with a kParseStackBytes stack and waits for it; false
/// with `why` when no such thread can be made or `work` throws.
bool onLargeStack(const std::function<bool()>& work, std::string& why) {
  struct Job {
    const std::function<bool()>* work;
    bool ok = false;
    std::string error;
  } job{&work, false, {}};
  auto run = [](void* arg) -> void* {
    auto* j = static_cast<Job*>(arg);
    try {
      j->ok = (*j->work)();
    } catch (const std::exception& e) {
      j->error = e.what();
    } catch (...) {
      j->error = "the importer failed";
    }
    return nullptr;
  };
  pthread_attr_t attr;
  pthread_t thread;
  bool started = pthread_attr_init(&attr) == 0;
  started = started && pthread_attr_setstacksize(&attr, kParseStackBytes) == 0 &&
            pthread_create(&thread, &attr, run, &job) == 0;
  pthread_attr_destroy(&attr);
  if (!started) {
    why = "cannot start a thread to read it";
    return false;
  }
  pthread_join(thread, nullptr);
  if (!job.error.empty()) why = job.error;
  return job.ok && job.error.empty();
}

// --- across the process boundary ---------------------------------------------------------

/// A MeshData as bytes, for the child that reads the file to hand it to the parent.
class MeshWriter {
 public:
  std::string bytes;
  void count(std::size_t n) { raw(&n, sizeof n); }
  void text(const std::string& s) {
    count(s.size());
    bytes += s;
  }
  template <typename T>
  void array(const std::vector<T>& v) {
    count(v.size());
    raw(v.data(), v.size() * sizeof(T));
  }
  template <typename T>
  void value(const T& v) { raw(&v, sizeof v); }
  void raw(const void* data, std::size_t size) { bytes.append(static_cast<const char*>(data), size); }
};

/// Reads what MeshWriter wrote; every read checks that the bytes hold it.
class MeshReader {
 public:
  explicit MeshReader(std::string_view bytes) : rest_(bytes) {}
  bool count(std::size_t& n) { return raw(&n, sizeof n); }
  bool text(std::string& s) {
    std::size_t n = 0;
    if (!count(n) || n > rest_.size()) return false;
    s.assign(rest_.substr(0, n));
    rest_.remove_prefix(n);
    return true;
  }
  template <typename T>
  bool array(std::vector<T>& v) {
    std::size_t n = 0;
    if (!count(n) || n > rest_.size() / sizeof(T)) return false;
    v.resize(n);
    return raw(v.data(), n * sizeof(T));
  }
  template <typename T>
  bool value(T& v) { return raw(&v, sizeof v); }
  bool raw(void* data, std::size_t size) {
    if (size > rest_.size()) return false;
    if (size > 0) std::memcpy(data, rest_.data(), size);
    rest_.remove_prefix(size);
    return true;
  }
  [[nodiscard]] bool done() const { return rest_.empty(); }

 private:
  std::string_view rest_;
};

std::string encode(const MeshData& mesh) {
  MeshWriter w;
  w.count(mesh.materials.size());
  for (const auto& m : mesh.materials) {
    w.text(m.name);
    for (const auto* c : {&m.ambient, &m.diffuse, &m.specular, &m.emissive}) w.value(*c);
    w.value(m.shininess);
    w.value(m.transparency);
  }
  w.count(mesh.parts.size());
  for (const auto& p : mesh.parts) {
    w.text(p.name);
    w.array(p.positions);
    w.array(p.normals);
    w.array(p.indices);
    w.value(p.material);
  }
  return std::move(w.bytes);
}

bool decode(std::string_view bytes, MeshData& mesh) {
  MeshReader r(bytes);
  std::size_t n = 0;
  if (!r.count(n) || n > bytes.size()) return false;
  mesh.materials.resize(n);
  for (auto& m : mesh.materials) {
    if (!r.text(m.name)) return false;
    for (auto* c : {&m.ambient, &m.diffuse, &m.specular, &m.emissive}) {
      if (!r.value(*c)) return false;
    }
    if (!r.value(m.shininess) || !r.value(m.transparency)) return false;
  }
  if (!r.count(n) || n > bytes.size()) return false;
  mesh.parts.resize(n);
  for (auto& p : mesh.parts) {
    if (!r.text(p.name) || !r.array(p.positions) || !r.array(p.normals) || !r.array(p.indices) || !r.value(p.material)) {
      return false;
    }
  }
  return r.done();
}

/// How long a library may take over a file of `bytes` (s): 5 s and 1 s per MiB begun.
double readSeconds(std::uintmax_t bytes) { return 5.0 + std::ceil(static_cast<double>(bytes) / (1 << 20)); }

/// How much memory a library may take over a file of `bytes`: 2 GiB and 64 times the file.
std::size_t readMemory(std::uintmax_t bytes) { return (std::size_t{2} << 30) + 64 * static_cast<std::size_t>(bytes); }

// --- Assimp ------------------------------------------------------------------------------

std::array<double, 3> color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                            std::array<double, 3> fallback) {
  aiColor3D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return fallback;
  return {std::clamp(core::widenFloat(c.r), 0.0, 1.0), std::clamp(core::widenFloat(c.g), 0.0, 1.0),
          std::clamp(core::widenFloat(c.b), 0.0, 1.0)};
}

/// Sets `mesh`'s primitive types from its faces (points, lines, triangles, polygons).
void countPrimitiveTypes(aiMesh& mesh) {
  unsigned types = 0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const unsigned n = mesh.mFaces[f].mNumIndices;
    types |= n == 1 ? aiPrimitiveType_POINT : n == 2 ? aiPrimitiveType_LINE : n == 3 ? aiPrimitiveType_TRIANGLE
                                                                                     : aiPrimitiveType_POLYGON;
  }
  mesh.mPrimitiveTypes = types;
}

bool readWithAssimp(const std::string& path, MeshData& mesh, std::string& why) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // read and check the file's structure first; the steps after it trust each mesh's
  // primitive types, which some loaders (PLY) get wrong on malformed files: Triangulate then
  // aborts the process (an ai_assert), so the types are counted again from the faces
  const aiScene* s = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (s != nullptr && (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) == 0) {
    for (unsigned i = 0; i < s->mNumMeshes; ++i) countPrimitiveTypes(*s->mMeshes[i]);
    s = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                     aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices |
                                     aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  }
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
    // (what a 32-bit number says, and the results at that precision: 0.3, not 0.30000000000000004)
    if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS) {
      out.shininess = std::clamp(core::widenFloat(static_cast<float>(core::widenFloat(shininess) / 128.0)), 0.0, 1.0);
    }
    if (m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) {
      out.transparency = std::clamp(core::widenFloat(static_cast<float>(1.0 - core::widenFloat(opacity))), 0.0, 1.0);
    }
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
  const auto rgb = [](const SbColor& c) {
    return std::array<double, 3>{core::widenFloat(c[0]), core::widenFloat(c[1]), core::widenFloat(c[2])};
  };
  m.ambient = rgb(ambient);
  m.diffuse = rgb(diffuse);
  m.specular = rgb(specular);
  m.emissive = rgb(emission);
  m.shininess = core::widenFloat(shininess);  // Coin's 0.2F is 0.2
  m.transparency = core::widenFloat(transparency);
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

/// Starts Coin and routes its messages to coinError (once).
void initCoin() {
  static std::once_flag once;
  std::call_once(once, [] {
    SoDB::init();
    SoReadError::setHandlerCallback(coinError, nullptr);
    SoDebugError::setHandlerCallback(coinError, nullptr);
  });
}

bool readWithCoin(const std::string& path, MeshData& mesh, std::string& why) {
  initCoin();
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

std::shared_ptr<const MeshData> readMesh(const std::string& path, std::string& why) {
  // Coin reports through globals and neither library promises to be reentrant: one read at a time
  static std::mutex mutex;
  const auto size = core::inputFileSize(path, why);
  if (!size) return nullptr;
  const std::string ext = extensionOf(path);
  if (!isMeshFile(path)) {
    why = "unsupported mesh format '" + ext + "' (gdpn reads obj, stl, 3ds, gltf, glb, dae, ply, wrl, iv)";
    return nullptr;
  }
  const bool coin = ext == ".wrl" || ext == ".iv";
  std::lock_guard lock(mutex);
  if (!precheck(path, ext, why)) return nullptr;
  if (coin) initCoin();  // once, here, so that no child pays for it
  // The libraries crash, abort and loop on some malformed files the checks above let through:
  // they read in a child process, bounded in time and memory, and hand back the mesh as bytes.
  // They recurse per level of nesting, so they get a stack of our choosing there.
  std::string bytes;
  const auto end = core::runInChild(
      [&](std::string& out, std::string& error) {
        MeshData read;
        if (!onLargeStack([&] { return coin ? readWithCoin(path, read, error) : readWithAssimp(path, read, error); },
                          error)) {
          return false;
        }
        out = encode(read);
        return true;
      },
      readSeconds(*size), readMemory(*size), bytes, why);
  if (end == core::ChildEnd::lost) why = std::string(coin ? "Coin3D" : "Assimp") + " " + why + " reading it";
  if (end != core::ChildEnd::done) return nullptr;
  auto mesh = std::make_shared<MeshData>();
  if (!decode(bytes, *mesh)) {
    why = "the reading process sent back a mesh that does not decode";
    return nullptr;
  }
  mesh->path = path;
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
  return mesh;
}

std::shared_ptr<const MeshData> loadMesh(const std::string& path, std::string& why) {
  namespace fs = std::filesystem;
  static std::mutex mutex;
  struct Entry {
    fs::file_time_type time;
    std::uintmax_t size = 0;
    std::shared_ptr<const MeshData> mesh;
  };
  static std::map<std::string, Entry> cache;

  const auto size = core::inputFileSize(path, why);
  if (!size) return nullptr;
  std::error_code ec;
  const auto time = fs::last_write_time(path, ec);
  std::lock_guard lock(mutex);
  if (auto it = cache.find(path); it != cache.end() && it->second.time == time && it->second.size == *size) {
    return it->second.mesh;
  }
  auto mesh = readMesh(path, why);
  if (mesh) cache[path] = {time, *size, mesh};
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
