#pragma once
// OpenGL 3.3 core drawing of a deformed surface: lit triangles with a colour per node, and wireframes (the FEM ghost,
// the rest shape). Needs a current context; everything is uploaded per frame (the state changes every frame).
#include <Eigen/Dense>
#include <array>
#include <hooke/core/types.hpp>
#include <string>
#include <vector>

#include "camera.hpp"

namespace hooke::viewer {

class Renderer {
 public:
  /// Compiles the shaders and makes the buffers for `triangles` (#F x 3) and `edges`.
  /// @throws Error when a shader does not compile (the driver's log in the message)
  Renderer(const RowMatXi& triangles, const std::vector<std::array<int, 2>>& edges);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void clear(int width, int height);
  /// The surface at `positions` (#V x 3, m) with one RGB colour per node, lit from the camera.
  void draw_surface(const RowMatX& positions, const std::vector<std::array<float, 3>>& colours, const Mat4f& view,
                    const Mat4f& projection);
  /// The surface's edges at `positions` in one colour.
  void draw_wireframe(const RowMatX& positions, const std::array<float, 3>& colour, const Mat4f& view,
                      const Mat4f& projection);
  /// Reads the framebuffer (RGB, origin bottom left) of a width x height viewport.
  std::vector<unsigned char> read_pixels(int width, int height) const;

 private:
  void upload(const RowMatX& positions, const std::vector<std::array<float, 3>>* colours);
  unsigned m_program = 0, m_vao = 0, m_vbo = 0, m_triangle_ibo = 0, m_edge_ibo = 0;
  int m_triangle_indices = 0, m_edge_indices = 0;
  RowMatXi m_triangles;
  std::vector<float> m_vertices;  // per node: position, normal, colour
};

/// Writes RGB pixels (origin bottom left, as read_pixels gives them) as a PNG, atomically.
/// @throws IoError when it cannot be written
void write_png(const std::string& path, const std::vector<unsigned char>& rgb, int width, int height);

}  // namespace hooke::viewer
