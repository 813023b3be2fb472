#pragma once
/// \file
/// Terrain on the GPU, in chunks with levels of detail.

#include <epoxy/gl.h>

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "gdpn/scene/terrain.h"

namespace gdpn::render::detail {

/// A terrain on the GPU: chunks of 64 x 64 cells sharing one vertex buffer, an index buffer
/// per level of detail (every 2^l-th vertex) with skirts that hide the cracks between levels.
struct TerrainGpu {
  static constexpr int kCells = 64;                            ///< cells along a chunk's side
  static constexpr int kSide = kCells + 1;                     ///< vertices along a chunk's side
  static constexpr int kLevels = 7;                            ///< levels of detail: steps 1, 2, ..., 64
  static constexpr int kPerChunk = kSide * kSide + 4 * kSide;  ///< vertices per chunk, skirts included
  /// One square of kCells x kCells cells.
  struct Chunk {
    glm::vec3 lo, hi;                    ///< bounding box in the terrain's frame, m
    std::array<float, kLevels> error{};  ///< the most each level moves a vertex, m
  };
  GLuint vao = 0, vbo = 0;               ///< vertex array, vertex buffer (every chunk's vertices)
  std::array<GLuint, kLevels> ibo{};     ///< index buffer per level (one chunk's triangles)
  std::array<GLsizei, kLevels> count{};  ///< indices per level
  std::vector<Chunk> chunks;             ///< row by row
  int cx = 0, cy = 0;                    ///< chunks across and down
  float cell = 1.0f;                     ///< the larger side of a cell, m

  /// Uploads `grid` as a terrain `width` x `depth` m across, heights times `hscale`; false when
  /// the grid has too few samples. Needs a current context.
  bool build(const scene::HeightGrid& grid, double width, double depth, double hscale);
  /// Frees the buffers.
  void release();
};

}  // namespace gdpn::render::detail
