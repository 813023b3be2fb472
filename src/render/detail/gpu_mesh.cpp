#include "gpu_mesh.h"

namespace gdpn::render::detail {

void GpuMesh::upload(const std::vector<float>& interleaved, const std::vector<std::uint32_t>& indices) {
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
               indices.data(), GL_STATIC_DRAW);
  pointAtInterleaved();
  glBindVertexArray(0);
  count = static_cast<GLsizei>(indices.size());
}

void GpuMesh::release() {
  if (vao != 0) glDeleteVertexArrays(1, &vao);
  if (vbo != 0) glDeleteBuffers(1, &vbo);
  if (ibo != 0) glDeleteBuffers(1, &ibo);
  vao = vbo = ibo = 0;
}

void pointAtInterleaved() {
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
}

}  // namespace gdpn::render::detail
