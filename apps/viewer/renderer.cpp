#define GL_GLEXT_PROTOTYPES 1
#include "renderer.hpp"

#include <GL/glcorearb.h>
#include <stb_image_write.h>

#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>

namespace hooke::viewer {
namespace {

// Lambert shading with a head light plus an ambient term; both faces lit (the normal flipped toward the eye). A
// uniform switches lighting off for wireframes.
constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 view;
uniform mat4 projection;
out vec3 view_normal;
out vec3 view_position;
out vec3 vertex_colour;
void main() {
  vec4 p = view * vec4(position, 1.0);
  view_position = p.xyz;
  view_normal = mat3(view) * normal;
  vertex_colour = colour;
  gl_Position = projection * p;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 view_normal;
in vec3 view_position;
in vec3 vertex_colour;
uniform int lit;
uniform vec3 flat_colour;
out vec4 fragment;
void main() {
  if (lit == 0) { fragment = vec4(flat_colour, 1.0); return; }
  vec3 n = normalize(view_normal);
  vec3 to_eye = normalize(-view_position);
  if (dot(n, to_eye) < 0.0) n = -n;
  float diffuse = max(dot(n, to_eye), 0.0);
  fragment = vec4(vertex_colour * (0.35 + 0.65 * diffuse), 1.0);
}
)";

unsigned compile(GLenum type, const char* source) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetShaderInfoLog(s, sizeof(log), nullptr, log);
    throw Error(std::string("the viewer's shader does not compile: ") + log);
  }
  return s;
}

}  // namespace

Renderer::Renderer(const RowMatXi& triangles, const std::vector<std::array<int, 2>>& edges) : m_triangles(triangles) {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader), fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  m_program = glCreateProgram();
  glAttachShader(m_program, vs);
  glAttachShader(m_program, fs);
  glLinkProgram(m_program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(m_program, GL_LINK_STATUS, &ok);
  if (!ok) throw Error("the viewer's shaders do not link");

  glGenVertexArrays(1, &m_vao);
  glBindVertexArray(m_vao);
  glGenBuffers(1, &m_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
  constexpr GLsizei stride = 9 * sizeof(float);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(6 * sizeof(float)));
  for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);

  std::vector<unsigned> tri(static_cast<size_t>(triangles.size()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) tri[static_cast<size_t>(3 * f + k)] = static_cast<unsigned>(triangles(f, k));
  std::vector<unsigned> lines;
  for (const auto& e : edges) lines.insert(lines.end(), {static_cast<unsigned>(e[0]), static_cast<unsigned>(e[1])});
  glGenBuffers(1, &m_triangle_ibo);
  glGenBuffers(1, &m_edge_ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_edge_ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(unsigned)), lines.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_triangle_ibo);  // bound last: the VAO keeps the triangles' indices
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(tri.size() * sizeof(unsigned)), tri.data(),
               GL_STATIC_DRAW);
  m_triangle_indices = static_cast<int>(tri.size());
  m_edge_indices = static_cast<int>(lines.size());
  glBindVertexArray(0);
}

Renderer::~Renderer() {
  glDeleteBuffers(1, &m_vbo);
  glDeleteBuffers(1, &m_triangle_ibo);
  glDeleteBuffers(1, &m_edge_ibo);
  glDeleteVertexArrays(1, &m_vao);
  glDeleteProgram(m_program);
}

void Renderer::clear(int width, int height) {
  glViewport(0, 0, width, height);
  glClearColor(0.93f, 0.93f, 0.94f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void Renderer::upload(const RowMatX& x, const std::vector<std::array<float, 3>>* colours) {
  const Eigen::Index n = x.rows();
  // Area-weighted node normals of the surface triangles.
  RowMatX normals = RowMatX::Zero(n, 3);
  for (Eigen::Index f = 0; f < m_triangles.rows(); ++f) {
    const int a = m_triangles(f, 0), b = m_triangles(f, 1), c = m_triangles(f, 2);
    const Vec3 ab = (x.row(b) - x.row(a)).transpose(), ac = (x.row(c) - x.row(a)).transpose();
    const Eigen::RowVector3d nf = ab.cross(ac).transpose();
    normals.row(a) += nf;
    normals.row(b) += nf;
    normals.row(c) += nf;
  }
  m_vertices.resize(static_cast<size_t>(9 * n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const double len = normals.row(i).norm();
    float* v = &m_vertices[static_cast<size_t>(9 * i)];
    for (int a = 0; a < 3; ++a) {
      v[a] = static_cast<float>(x(i, a));
      v[3 + a] = static_cast<float>(len > 0.0 ? normals(i, a) / len : 0.0);
      v[6 + a] = colours ? (*colours)[static_cast<size_t>(i)][static_cast<size_t>(a)] : 0.0f;
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m_vertices.size() * sizeof(float)), m_vertices.data(),
               GL_STREAM_DRAW);
}

void Renderer::draw_surface(const RowMatX& x, const std::vector<std::array<float, 3>>& colours, const Mat4f& view,
                            const Mat4f& projection) {
  glUseProgram(m_program);
  glBindVertexArray(m_vao);
  upload(x, &colours);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);  // wireframes drawn on the surface stay visible
  glUniformMatrix4fv(glGetUniformLocation(m_program, "view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(glGetUniformLocation(m_program, "projection"), 1, GL_FALSE, projection.data());
  glUniform1i(glGetUniformLocation(m_program, "lit"), 1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_triangle_ibo);
  glDrawElements(GL_TRIANGLES, m_triangle_indices, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindVertexArray(0);
}

void Renderer::draw_wireframe(const RowMatX& x, const std::array<float, 3>& colour, const Mat4f& view,
                              const Mat4f& projection) {
  glUseProgram(m_program);
  glBindVertexArray(m_vao);
  upload(x, nullptr);
  glEnable(GL_DEPTH_TEST);
  glUniformMatrix4fv(glGetUniformLocation(m_program, "view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(glGetUniformLocation(m_program, "projection"), 1, GL_FALSE, projection.data());
  glUniform1i(glGetUniformLocation(m_program, "lit"), 0);
  glUniform3f(glGetUniformLocation(m_program, "flat_colour"), colour[0], colour[1], colour[2]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_edge_ibo);
  glDrawElements(GL_LINES, m_edge_indices, GL_UNSIGNED_INT, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_triangle_ibo);  // the VAO's element buffer back to the triangles
  glBindVertexArray(0);
}

std::vector<unsigned char> Renderer::read_pixels(int width, int height) const {
  std::vector<unsigned char> rgb(static_cast<size_t>(3 * width * height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  return rgb;
}

void write_png(const std::string& path, const std::vector<unsigned char>& rgb, int width, int height) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        stbi_flip_vertically_on_write(1);  // GL's rows start at the bottom
        auto sink = [](void* context, void* data, int size) {
          static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
        };
        if (!stbi_write_png_to_func(sink, &out, width, height, 3, rgb.data(), 3 * width))
          throw IoError("cannot encode the screenshot " + path);
      },
      true);
}

}  // namespace hooke::viewer
