#include "reconfig/render/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "detail/gl_program.h"
#include "reconfig/render/render_target.h"

namespace reconfig::render {
namespace {

using detail::check_gl;
using detail::link_program;
using detail::make_indexed_positions_vao;

// Lit surfaces. Normals come from screen-space derivatives of the eye-space position: flat
// shading without duplicating vertices, and always facing the viewer (two-sided).
constexpr const char* kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
out vec3 eye_position;
void main() {
  vec4 p = view * (model * vec4(position, 1.0));
  eye_position = p.xyz;
  gl_Position = projection * p;
}
)";

constexpr const char* kSurfaceFragment = R"(#version 330 core
in vec3 eye_position;
uniform vec3 color;
uniform float opacity;
uniform int highlighted;
out vec4 fragment;
void main() {
  vec3 n = normalize(cross(dFdx(eye_position), dFdy(eye_position)));
  vec3 to_eye = normalize(-eye_position);
  if (dot(n, to_eye) < 0.0) n = -n;
  const vec3 key = normalize(vec3(0.45, 0.65, 0.6));
  const vec3 fill = normalize(vec3(-0.6, -0.2, 0.75));
  float light = 0.28 + 0.62 * max(dot(n, key), 0.0) + 0.25 * max(dot(n, fill), 0.0);
  vec3 c = color * light;
  if (highlighted != 0) {
    const vec3 glow = vec3(1.0, 0.62, 0.1);
    float rim = pow(1.0 - max(dot(n, to_eye), 0.0), 2.0);
    c = mix(c, glow, 0.35) + glow * rim * 0.8;
  }
  fragment = vec4(min(c, vec3(1.0)), opacity);
}
)";

// Unlit colored geometry: lines, grid, box faces and edges.
constexpr const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
uniform mat4 view_projection;
out vec4 vertex_color;
void main() {
  vertex_color = color;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

constexpr const char* kFlatFragment = R"(#version 330 core
in vec4 vertex_color;
out vec4 fragment;
void main() { fragment = vertex_color; }
)";

struct ColoredVertex {
  float x, y, z, r, g, b, a;
};

void push(std::vector<ColoredVertex>& out, const Eigen::Vector3d& p, const Eigen::Vector4f& c) {
  out.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), c[0], c[1], c[2], c[3]});
}

// A cone along `axis` from `base` (radius r) to `tip`, `sides` triangles around plus the base.
void cone_mesh(const Eigen::Vector3d& base, const Eigen::Vector3d& tip, double radius, int sides, Eigen::MatrixX3d& V,
               Eigen::MatrixX3i& F) {
  const Eigen::Vector3d axis = (tip - base).normalized();
  Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  V.resize(sides + 2, 3);
  F.resize(2 * sides, 3);
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * M_PI * i / sides;
    V.row(i) = (base + radius * (std::cos(a) * u + std::sin(a) * v)).transpose();
  }
  V.row(sides) = tip.transpose();
  V.row(sides + 1) = base.transpose();
  for (int i = 0; i < sides; ++i) {
    const int j = (i + 1) % sides;
    F.row(i) << i, j, sides;
    F.row(sides + i) << j, i, sides + 1;
  }
}

Eigen::Matrix4f to_float(const Eigen::Matrix4d& m) { return m.cast<float>(); }

}  // namespace

struct Renderer::Impl {
  GLuint surface_program = 0, flat_program = 0;
  GLint surface_model = -1, surface_view = -1, surface_projection = -1, surface_color = -1, surface_opacity = -1,
        surface_highlighted = -1;
  GLint flat_view_projection = -1;
  GLuint mesh_vao = 0, mesh_vbo = 0, mesh_ebo = 0;
  GLuint flat_vao = 0, flat_vbo = 0;
  // Offscreen targets: multisampled (color + depth) resolved into a single-sample color buffer.
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0, resolve_fbo = 0, resolve_color = 0;
  int fbo_width = 0, fbo_height = 0;
  int samples = 0;

  /// Rest meshes kept on the GPU, by object; an entry whose object died is released.
  struct ResidentMesh {
    std::weak_ptr<const geometry::Mesh> owner;
    GLuint vao = 0, vbo = 0, ebo = 0;
    GLsizei indices = 0;
  };
  std::unordered_map<const geometry::Mesh*, ResidentMesh> resident;

  void ensure_targets(int width, int height);
  const ResidentMesh& make_resident(const std::shared_ptr<const geometry::Mesh>& mesh);
  void release_dead_meshes();
  void draw_mesh(const MeshItem& mesh);
  void draw_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const Eigen::Vector3f& color, float opacity,
                 bool highlighted);
  void draw_flat(const std::vector<ColoredVertex>& vertices, GLenum mode);
  void release_targets();
};

Renderer::Renderer(const RendererOptions& options) : impl_(std::make_unique<Impl>()) {
  Impl& r = *impl_;
  r.surface_program = link_program(kSurfaceVertex, kSurfaceFragment);
  r.surface_model = glGetUniformLocation(r.surface_program, "model");
  r.surface_view = glGetUniformLocation(r.surface_program, "view");
  r.surface_projection = glGetUniformLocation(r.surface_program, "projection");
  r.surface_color = glGetUniformLocation(r.surface_program, "color");
  r.surface_opacity = glGetUniformLocation(r.surface_program, "opacity");
  r.surface_highlighted = glGetUniformLocation(r.surface_program, "highlighted");
  r.flat_program = link_program(kFlatVertex, kFlatFragment);
  r.flat_view_projection = glGetUniformLocation(r.flat_program, "view_projection");

  make_indexed_positions_vao(r.mesh_vao, r.mesh_vbo, r.mesh_ebo);

  glGenVertexArrays(1, &r.flat_vao);
  glGenBuffers(1, &r.flat_vbo);
  glBindVertexArray(r.flat_vao);
  glBindBuffer(GL_ARRAY_BUFFER, r.flat_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ColoredVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ColoredVertex), reinterpret_cast<void*>(3 * sizeof(float)));
  glBindVertexArray(0);

  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  r.samples = options.samples > 1 ? std::min(options.samples, static_cast<int>(max_samples)) : 0;
  check_gl("creating the renderer");
}

Renderer::~Renderer() {
  Impl& r = *impl_;
  r.release_targets();
  for (auto& [key, mesh] : r.resident) {
    glDeleteBuffers(1, &mesh.vbo);
    glDeleteBuffers(1, &mesh.ebo);
    glDeleteVertexArrays(1, &mesh.vao);
  }
  glDeleteBuffers(1, &r.mesh_vbo);
  glDeleteBuffers(1, &r.mesh_ebo);
  glDeleteBuffers(1, &r.flat_vbo);
  glDeleteVertexArrays(1, &r.mesh_vao);
  glDeleteVertexArrays(1, &r.flat_vao);
  glDeleteProgram(r.surface_program);
  glDeleteProgram(r.flat_program);
}

int Renderer::samples() const { return impl_->samples; }

void Renderer::Impl::release_targets() {
  glDeleteFramebuffers(1, &msaa_fbo);
  glDeleteFramebuffers(1, &resolve_fbo);
  glDeleteRenderbuffers(1, &msaa_color);
  glDeleteRenderbuffers(1, &msaa_depth);
  glDeleteRenderbuffers(1, &resolve_color);
  msaa_fbo = resolve_fbo = msaa_color = msaa_depth = resolve_color = 0;
  fbo_width = fbo_height = 0;
}

void Renderer::Impl::ensure_targets(int width, int height) {
  if (width == fbo_width && height == fbo_height) return;
  release_targets();
  glGenFramebuffers(1, &msaa_fbo);
  glGenRenderbuffers(1, &msaa_color);
  glGenRenderbuffers(1, &msaa_depth);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("render: the multisampled framebuffer is incomplete");
  glGenFramebuffers(1, &resolve_fbo);
  glGenRenderbuffers(1, &resolve_color);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo);
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("render: the resolve framebuffer is incomplete");
  fbo_width = width;
  fbo_height = height;
}

void Renderer::Impl::draw_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const Eigen::Vector3f& color,
                               float opacity, bool highlighted) {
  if (F.rows() == 0) return;
  const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> positions = V.cast<float>();
  const Eigen::Matrix<unsigned, Eigen::Dynamic, 3, Eigen::RowMajor> indices = F.cast<unsigned>();
  glBindVertexArray(mesh_vao);
  glBindBuffer(GL_ARRAY_BUFFER, mesh_vbo);
  glBufferData(GL_ARRAY_BUFFER, positions.size() * sizeof(float), positions.data(), GL_STREAM_DRAW);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(unsigned), indices.data(), GL_STREAM_DRAW);
  glUniform3f(surface_color, color[0], color[1], color[2]);
  glUniform1f(surface_opacity, opacity);
  glUniform1i(surface_highlighted, highlighted ? 1 : 0);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, nullptr);
}

const Renderer::Impl::ResidentMesh& Renderer::Impl::make_resident(const std::shared_ptr<const geometry::Mesh>& mesh) {
  ResidentMesh& entry = resident[mesh.get()];
  if (entry.vao && entry.owner.lock() == mesh) return entry;
  if (!entry.vao) {
    glGenVertexArrays(1, &entry.vao);
    glGenBuffers(1, &entry.vbo);
    glGenBuffers(1, &entry.ebo);
  }
  entry.owner = mesh;
  const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> positions = mesh->V.cast<float>();
  const Eigen::Matrix<unsigned, Eigen::Dynamic, 3, Eigen::RowMajor> indices = mesh->F.cast<unsigned>();
  glBindVertexArray(entry.vao);
  glBindBuffer(GL_ARRAY_BUFFER, entry.vbo);
  glBufferData(GL_ARRAY_BUFFER, positions.size() * sizeof(float), positions.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, entry.ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(unsigned), indices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  entry.indices = static_cast<GLsizei>(indices.size());
  return entry;
}

void Renderer::Impl::release_dead_meshes() {
  std::erase_if(resident, [](const auto& item) {
    const ResidentMesh& mesh = item.second;
    if (!mesh.owner.expired()) return false;
    glDeleteBuffers(1, &mesh.vbo);
    glDeleteBuffers(1, &mesh.ebo);
    glDeleteVertexArrays(1, &mesh.vao);
    return true;
  });
}

void Renderer::Impl::draw_mesh(const MeshItem& mesh) {
  if (mesh.cull_back_faces) glEnable(GL_CULL_FACE);
  else glDisable(GL_CULL_FACE);
  if (!mesh.rest) {
    glUniformMatrix4fv(surface_model, 1, GL_FALSE, Eigen::Matrix4f::Identity().eval().data());
    draw_mesh(mesh.V, mesh.F, mesh.color, mesh.opacity, mesh.highlighted);
    return;
  }
  if (mesh.rest->F.rows() == 0) return;
  const ResidentMesh& gpu = make_resident(mesh.rest);
  glUniformMatrix4fv(surface_model, 1, GL_FALSE, mesh.placement.matrix().cast<float>().eval().data());
  glUniform3f(surface_color, mesh.color[0], mesh.color[1], mesh.color[2]);
  glUniform1f(surface_opacity, mesh.opacity);
  glUniform1i(surface_highlighted, mesh.highlighted ? 1 : 0);
  glBindVertexArray(gpu.vao);
  glDrawElements(GL_TRIANGLES, gpu.indices, GL_UNSIGNED_INT, nullptr);
}

void Renderer::Impl::draw_flat(const std::vector<ColoredVertex>& vertices, GLenum mode) {
  if (vertices.empty()) return;
  glBindVertexArray(flat_vao);
  glBindBuffer(GL_ARRAY_BUFFER, flat_vbo);
  glBufferData(GL_ARRAY_BUFFER, vertices.size() * sizeof(ColoredVertex), vertices.data(), GL_STREAM_DRAW);
  glDrawArrays(mode, 0, static_cast<GLsizei>(vertices.size()));
}

void Renderer::draw(const DrawList& list, const view::Camera& camera, int width, int height) {
  Impl& r = *impl_;
  r.release_dead_meshes();
  const double aspect = static_cast<double>(width) / height;
  const Eigen::Matrix4f view = to_float(camera.view_matrix());
  const Eigen::Matrix4f projection = to_float(camera.projection_matrix(aspect));
  const Eigen::Matrix4f view_projection = projection * view;
  const Eigen::Vector3d eye = camera.eye();

  glViewport(0, 0, width, height);
  glClearColor(list.background[0], list.background[1], list.background[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  // Colors blend by alpha; the destination alpha stays 1 (opaque PNGs).
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (r.samples > 0) glEnable(GL_MULTISAMPLE);

  // Arrow heads become lit cones; their shafts lines.
  std::vector<MeshItem> cones;
  std::vector<ColoredVertex> lines;
  for (const ArrowItem& arrow : list.arrows) {
    const double length = (arrow.to - arrow.from).norm();
    if (length <= 0) continue;
    const Eigen::Vector3d base = arrow.to + (arrow.from - arrow.to) * arrow.head_fraction;
    MeshItem cone;
    cone_mesh(base, arrow.to, 0.35 * arrow.head_fraction * length, 16, cone.V, cone.F);
    cone.color = arrow.color;
    cones.push_back(std::move(cone));
    const Eigen::Vector4f c(arrow.color[0], arrow.color[1], arrow.color[2], 1.0f);
    push(lines, arrow.from, c);
    push(lines, base, c);
  }

  // 1. Solid meshes.
  glUseProgram(r.surface_program);
  glUniformMatrix4fv(r.surface_view, 1, GL_FALSE, view.data());
  glUniformMatrix4fv(r.surface_projection, 1, GL_FALSE, projection.data());
  glDepthMask(GL_TRUE);
  for (const MeshItem& mesh : list.meshes)
    if (mesh.opacity >= 1.0f) r.draw_mesh(mesh);
  for (const MeshItem& cone : cones) r.draw_mesh(cone);
  glDisable(GL_CULL_FACE);

  // 2. Grid, lines and arrow shafts (depth tested, blended, not occluding transparent items).
  glUseProgram(r.flat_program);
  glUniformMatrix4fv(r.flat_view_projection, 1, GL_FALSE, view_projection.data());
  std::vector<ColoredVertex> grid;
  if (list.grid.visible && list.grid.spacing > 0 && list.grid.half_lines > 0) {
    const GridItem& g = list.grid;
    const double extent = g.spacing * g.half_lines;
    for (int i = -g.half_lines; i <= g.half_lines; ++i) {
      const double x = g.center.x() + i * g.spacing, y = g.center.y() + i * g.spacing;
      const bool x_axis = std::abs(y) < 1e-6 * g.spacing;  // the line y = 0 is the x axis
      const bool y_axis = std::abs(x) < 1e-6 * g.spacing;
      const Eigen::Vector4f along_x = x_axis ? Eigen::Vector4f(0.85f, 0.2f, 0.2f, 0.9f) : g.color;
      const Eigen::Vector4f along_y = y_axis ? Eigen::Vector4f(0.2f, 0.7f, 0.25f, 0.9f) : g.color;
      push(grid, {g.center.x() - extent, y, g.height}, along_x);
      push(grid, {g.center.x() + extent, y, g.height}, along_x);
      push(grid, {x, g.center.y() - extent, g.height}, along_y);
      push(grid, {x, g.center.y() + extent, g.height}, along_y);
    }
  }
  glDepthMask(GL_FALSE);
  r.draw_flat(grid, GL_LINES);
  glDepthMask(GL_TRUE);
  for (const LineItem& line : list.lines) {
    std::vector<ColoredVertex> vertices;
    for (const Eigen::Vector3d& p : line.points) push(vertices, p, line.color);
    r.draw_flat(vertices, line.strip ? GL_LINE_STRIP : GL_LINES);
  }
  r.draw_flat(lines, GL_LINES);

  // 3. Transparent items, farthest first: ghosts and boxes; no depth writes.
  struct Transparent {
    double distance;
    const MeshItem* mesh;
    const BoxItem* box;
  };
  std::vector<Transparent> transparent;
  for (const MeshItem& mesh : list.meshes) {
    if (mesh.opacity >= 1.0f) continue;
    if (mesh.rest && mesh.rest->V.rows() > 0)
      transparent.push_back(
          {(mesh.placement * Eigen::Vector3d(mesh.rest->V.colwise().mean().transpose()) - eye).norm(), &mesh, nullptr});
    else if (!mesh.rest && mesh.V.rows() > 0)
      transparent.push_back({(mesh.V.colwise().mean().transpose() - eye).norm(), &mesh, nullptr});
  }
  for (const BoxItem& box : list.boxes)
    if (!box.box.isEmpty()) transparent.push_back({(box.box.center() - eye).norm(), nullptr, &box});
  std::stable_sort(transparent.begin(), transparent.end(),
                   [](const Transparent& a, const Transparent& b) { return a.distance > b.distance; });
  glDepthMask(GL_FALSE);
  const float pulse = 0.75f + 0.25f * static_cast<float>(std::sin(2 * M_PI * list.seconds));
  for (const Transparent& item : transparent) {
    if (item.mesh) {
      glUseProgram(r.surface_program);
      r.draw_mesh(*item.mesh);
      glDisable(GL_CULL_FACE);
      continue;
    }
    const BoxItem& b = *item.box;
    const float alpha = std::clamp(b.opacity * (b.pulsate ? pulse : 1.0f), 0.0f, 1.0f);
    const Eigen::Vector4f face(b.color[0], b.color[1], b.color[2], alpha);
    const Eigen::Vector4f edge(b.color[0] * 0.7f, b.color[1] * 0.7f, b.color[2] * 0.7f, std::min(1.0f, 0.5f + alpha));
    using Corner = Eigen::AlignedBox3d::CornerType;
    auto corner = [&](int bits) { return b.box.corner(static_cast<Corner>(bits)); };  // bit 0: x, 1: y, 2: z max
    static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<ColoredVertex> faces, edges;
    for (const auto& q : kQuads)
      for (int k : {0, 1, 2, 0, 2, 3}) push(faces, corner(q[k]), face);
    for (int a = 0; a < 8; ++a)
      for (int bit = 0; bit < 3; ++bit)
        if (!(a & (1 << bit))) {
          push(edges, corner(a), edge);
          push(edges, corner(a | (1 << bit)), edge);
        }
    glUseProgram(r.flat_program);
    if (b.on_top) {
      // The hidden part first, fainter and without depth test; then the visible part on top.
      std::vector<ColoredVertex> faint_faces = faces, faint_edges = edges;
      for (ColoredVertex& v : faint_faces) v.a *= 0.6f;
      for (ColoredVertex& v : faint_edges) v.a *= 0.6f;
      glDisable(GL_DEPTH_TEST);
      r.draw_flat(faint_faces, GL_TRIANGLES);
      r.draw_flat(faint_edges, GL_LINES);
      glEnable(GL_DEPTH_TEST);
    }
    r.draw_flat(faces, GL_TRIANGLES);
    r.draw_flat(edges, GL_LINES);
  }
  glDepthMask(GL_TRUE);
  glBindVertexArray(0);
  glUseProgram(0);
  check_gl("drawing");
}

Image Renderer::render(const DrawList& list, const view::Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("render: the image size must be positive");
  Impl& r = *impl_;
  r.ensure_targets(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, r.msaa_fbo);
  draw(list, camera, width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, r.msaa_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.resolve_fbo);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, r.resolve_fbo);
  Image image = read_bound_framebuffer(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("reading pixels");
  return image;
}

}  // namespace reconfig::render
