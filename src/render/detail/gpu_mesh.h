#pragma once
/// \file
/// Triangles on the GPU: vertices (position, normal) and the indices that join them.

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace gdpn::render::detail {

/// Vertices (position, normal) and triangles on the GPU. A plain handle: copies share the
/// buffers, and release() frees them (the owner calls it once, with the context current).
struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;  ///< vertex array, vertex buffer, index buffer
  GLsizei count = 0;                 ///< indices (three per triangle)
  /// Uploads `interleaved` vertices (x, y, z, nx, ny, nz each, m) and `indices` (three per
  /// triangle); needs a current context.
  void upload(const std::vector<float>& interleaved, const std::vector<std::uint32_t>& indices);
  /// Frees the buffers.
  void release();
};

/// Points attributes 0 (position) and 1 (normal) of the bound vertex array into the bound
/// vertex buffer, whose vertices are six floats each (x, y, z, nx, ny, nz).
void pointAtInterleaved();

}  // namespace gdpn::render::detail
