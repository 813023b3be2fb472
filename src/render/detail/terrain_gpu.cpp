#include "terrain_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "gpu_mesh.h"

namespace gdpn::render::detail {

bool TerrainGpu::build(const scene::HeightGrid& grid, double width, double depth, double hscale) {
  const int nx = grid.nx, ny = grid.ny;
  if (nx < 2 || ny < 2) return false;
  cx = (nx - 2) / kCells + 1;
  cy = (ny - 2) / kCells + 1;
  const double sx = width / (nx - 1), sy = depth / (ny - 1);
  cell = static_cast<float>(std::max(sx, sy));
  auto H = [&](int i, int j) {
    i = std::clamp(i, 0, nx - 1);
    j = std::clamp(j, 0, ny - 1);
    return grid.height[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)] * hscale;
  };
  auto P = [&](int i, int j) {
    return glm::vec3(static_cast<float>(-width / 2 + std::min(i, nx - 1) * sx),
                     static_cast<float>(depth / 2 - std::min(j, ny - 1) * sy), static_cast<float>(H(i, j)));
  };
  auto N = [&](int i, int j) {
    const double dx = (H(i + 1, j) - H(i - 1, j)) / (2 * sx), dy = (H(i, j - 1) - H(i, j + 1)) / (2 * sy);
    return glm::normalize(glm::vec3(static_cast<float>(-dx), static_cast<float>(-dy), 1.0f));
  };
  std::vector<float> v;
  v.reserve(static_cast<std::size_t>(cx * cy) * kPerChunk * 6);
  for (int by = 0; by < cy; ++by) {
    for (int bx = 0; bx < cx; ++bx) {
      Chunk c;
      c.lo = glm::vec3(1e30f);
      c.hi = glm::vec3(-1e30f);
      const int i0 = bx * kCells, j0 = by * kCells;
      for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) {
          const glm::vec3 p = P(i0 + i, j0 + j), n = N(i0 + i, j0 + j);
          v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
          c.lo = glm::min(c.lo, p);
          c.hi = glm::max(c.hi, p);
        }
      }
      const float skirt = (c.hi.z - c.lo.z) * 0.1f + cell;
      for (int e = 0; e < 4; ++e) {
        for (int k = 0; k < kSide; ++k) {
          const int i = e == 0 ? k : e == 1 ? k : e == 2 ? 0 : kCells;
          const int j = e == 0 ? 0 : e == 1 ? kCells : k;
          glm::vec3 p = P(i0 + i, j0 + j);
          p.z -= skirt;
          const glm::vec3 n = N(i0 + i, j0 + j);
          v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
        }
      }
      c.lo.z -= skirt;
      // each level's error: the largest height difference between a dropped vertex and
      // the level's (bilinear) surface over it
      for (int l = 1; l < kLevels; ++l) {
        const int s = 1 << l;
        float worst = 0;
        for (int j = 0; j < kSide; ++j) {
          for (int i = 0; i < kSide; ++i) {
            if (i % s == 0 && j % s == 0) continue;
            const int a = (i / s) * s, b = (j / s) * s;
            const int a1 = std::min(a + s, kCells), b1 = std::min(b + s, kCells);
            const double fx = a1 > a ? static_cast<double>(i - a) / (a1 - a) : 0.0;
            const double fy = b1 > b ? static_cast<double>(j - b) / (b1 - b) : 0.0;
            const double h = (1 - fx) * (1 - fy) * H(i0 + a, j0 + b) + fx * (1 - fy) * H(i0 + a1, j0 + b) +
                             (1 - fx) * fy * H(i0 + a, j0 + b1) + fx * fy * H(i0 + a1, j0 + b1);
            worst = std::max(worst, static_cast<float>(std::abs(h - H(i0 + i, j0 + j))));
          }
        }
        c.error[static_cast<std::size_t>(l)] = std::max(worst, c.error[static_cast<std::size_t>(l - 1)]);
      }
      chunks.push_back(c);
    }
  }
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
  pointAtInterleaved();
  for (int l = 0; l < kLevels; ++l) {
    const int s = 1 << l;
    std::vector<std::uint32_t> idx;
    auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * kSide + i); };
    auto skirtAt = [](int e, int k) { return static_cast<std::uint32_t>(kSide * kSide + e * kSide + k); };
    for (int j = 0; j < kCells; j += s) {
      for (int i = 0; i < kCells; i += s) {
        idx.insert(idx.end(), {at(i, j + s), at(i + s, j + s), at(i + s, j), at(i, j + s), at(i + s, j), at(i, j)});
      }
    }
    for (int k = 0; k < kCells; k += s) {
      // north (j = 0), south (j = kCells), west (i = 0), east (i = kCells): both windings,
      // a skirt is seen from either side
      const std::array<std::pair<std::uint32_t, std::uint32_t>, 4> top = {
          std::pair{at(k, 0), at(k + s, 0)}, std::pair{at(k, kCells), at(k + s, kCells)},
          std::pair{at(0, k), at(0, k + s)}, std::pair{at(kCells, k), at(kCells, k + s)}};
      for (int e = 0; e < 4; ++e) {
        const auto [a, b] = top[static_cast<std::size_t>(e)];
        const auto c = skirtAt(e, k + s), d = skirtAt(e, k);
        idx.insert(idx.end(), {a, b, c, a, c, d, a, c, b, a, d, c});
      }
    }
    glGenBuffers(1, &ibo[static_cast<std::size_t>(l)]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo[static_cast<std::size_t>(l)]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(),
                 GL_STATIC_DRAW);
    count[static_cast<std::size_t>(l)] = static_cast<GLsizei>(idx.size());
  }
  glBindVertexArray(0);
  return true;
}

void TerrainGpu::release() {
  if (vao != 0) glDeleteVertexArrays(1, &vao);
  if (vbo != 0) glDeleteBuffers(1, &vbo);
  for (auto b : ibo) {
    if (b != 0) glDeleteBuffers(1, &b);
  }
}

}  // namespace gdpn::render::detail
