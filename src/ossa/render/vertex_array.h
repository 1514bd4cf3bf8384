#pragma once
// VertexArray<Vertex> — a VAO with its vertex buffer and optional index buffer, one per
// vertex type ([T 4.3.1]). A vertex type describes its attribute layout with a static
// `layout()` returning the attributes in shader location order:
//
//   struct DebugVertex {
//     glm::vec2 position_ws; uint32_t rgba;
//     static std::span<const VertexAttrib> layout();  // {0: 2 floats}, {1: 4 normalised bytes}
//   };
//   VertexArray<DebugVertex> va;  va.upload(vertices);  va.draw(GL_LINES);
//
// Needs a current GL context for every call (construction included).

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

#include "ossa/render/gl.h"

namespace ossa {

// One vertex attribute: `components` values of `type` at byte `offset`. `integer` attributes
// reach the shader as int/uint (glVertexAttribIPointer); others as float, optionally normalised.
struct VertexAttrib {
  unsigned location = 0;
  int components = 1;           // 1..4
  unsigned type = GL_FLOAT;     // GL_FLOAT, GL_UNSIGNED_BYTE, GL_UNSIGNED_INT, ...
  bool normalized = false;
  bool integer = false;
  size_t offset = 0;            // bytes from the start of the vertex
};

template <class Vertex>
class VertexArray {
 public:
  VertexArray() {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glGenBuffers(1, &ebo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    for (const VertexAttrib& a : Vertex::layout()) {
      glEnableVertexAttribArray(a.location);
      const void* offset = reinterpret_cast<const void*>(a.offset);
      if (a.integer) {
        glVertexAttribIPointer(a.location, a.components, a.type, sizeof(Vertex), offset);
      } else {
        glVertexAttribPointer(a.location, a.components, a.type, a.normalized ? GL_TRUE : GL_FALSE,
                              sizeof(Vertex), offset);
      }
    }
    // The element buffer binding is VAO state: bind it while the VAO is bound.
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBindVertexArray(0);
  }
  ~VertexArray() { release(); }
  VertexArray(VertexArray&& o) noexcept { *this = std::move(o); }
  VertexArray& operator=(VertexArray&& o) noexcept {
    if (this != &o) {
      release();
      vao_ = std::exchange(o.vao_, 0u);
      vbo_ = std::exchange(o.vbo_, 0u);
      ebo_ = std::exchange(o.ebo_, 0u);
      vertex_count_ = std::exchange(o.vertex_count_, 0);
      index_count_ = std::exchange(o.index_count_, 0);
    }
    return *this;
  }
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;

  // Replaces the vertices (and the indices, when given). usage: GL_STATIC_DRAW for meshes
  // uploaded once, GL_STREAM_DRAW for debug geometry rebuilt every frame.
  void upload(std::span<const Vertex> vertices, std::span<const uint32_t> indices = {},
              unsigned usage = GL_STATIC_DRAW) {
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size_bytes()),
                 vertices.data(), usage);
    vertex_count_ = static_cast<int>(vertices.size());
    if (!indices.empty() || index_count_ != 0) {
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size_bytes()),
                   indices.data(), usage);
      index_count_ = static_cast<int>(indices.size());
    }
    glBindVertexArray(0);
  }

  // Draws every vertex (no indices) or every index.
  void draw(unsigned mode) const {
    if (index_count_ > 0) {
      draw_indices(mode, 0, index_count_);
    } else if (vertex_count_ > 0) {
      glBindVertexArray(vao_);
      glDrawArrays(mode, 0, vertex_count_);
    }
  }
  // Draws indices [first, first + count).
  void draw_indices(unsigned mode, int first, int count) const {
    if (count <= 0) return;
    glBindVertexArray(vao_);
    glDrawElements(mode, count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<size_t>(first) * sizeof(uint32_t)));
  }

  int vertex_count() const { return vertex_count_; }
  int index_count() const { return index_count_; }
  unsigned vao() const { return vao_; }

 private:
  void release() {
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (ebo_) glDeleteBuffers(1, &ebo_);
    vao_ = vbo_ = ebo_ = 0;
  }

  unsigned vao_ = 0, vbo_ = 0, ebo_ = 0;
  int vertex_count_ = 0;
  int index_count_ = 0;
};

}  // namespace ossa
