#include "reconfig/render/occlusion_counter.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

#include "detail/gl_program.h"

namespace reconfig::render {
namespace {

// Camera `gl_InstanceID` of the batch (occluders: one instance per camera), or the vertex's
// own `box_camera` (boxes: one copy per camera, drawn one range at a time without a state
// change between the queries), draws into its own tile of the atlas: its clip coordinates are
// clipped to its frustum's sides (gl_ClipDistance), then scaled into the tile. The
// view-projection matrices are columns of a buffer texture, 4 texels each.
constexpr const char* kTileVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in int box_camera;
uniform samplerBuffer view_projections;
uniform int instanced;
uniform int tiles_per_row;
out float gl_ClipDistance[4];
void main() {
  int camera = instanced != 0 ? gl_InstanceID : box_camera;
  mat4 m = mat4(texelFetch(view_projections, 4 * camera), texelFetch(view_projections, 4 * camera + 1),
                texelFetch(view_projections, 4 * camera + 2), texelFetch(view_projections, 4 * camera + 3));
  vec4 clip = m * vec4(position, 1.0);
  gl_ClipDistance[0] = clip.w + clip.x;
  gl_ClipDistance[1] = clip.w - clip.x;
  gl_ClipDistance[2] = clip.w + clip.y;
  gl_ClipDistance[3] = clip.w - clip.y;
  float k = float(tiles_per_row);
  vec2 tile = vec2(float(camera % tiles_per_row), float(camera / tiles_per_row));
  vec2 offset = (2.0 * tile + 1.0) / k - 1.0;
  gl_Position = vec4(clip.xy / k + clip.w * offset, clip.z, clip.w);
}
)";

constexpr const char* kDepthOnlyFragment = R"(#version 330 core
void main() {}
)";

// The 12 outward (counter-clockwise) triangles of a box, as 36 corner indices of
// Eigen::AlignedBox3d::corner (bit 0: x max, bit 1: y max, bit 2: z max).
constexpr std::array<int, 36> kBoxCorners = {0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                                             2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5};

constexpr int kMaxAtlasSide = 1024;

struct BoxVertex {
  float x, y, z;
  GLint camera;
};
constexpr int kMaxTilesPerRow = 16;

}  // namespace

struct OcclusionCounter::Impl {
  int resolution = 64, tiles_per_row = 1;
  GLuint program = 0;
  GLint instanced = -1;
  GLuint framebuffer = 0, depth = 0;
  GLuint matrices_buffer = 0, matrices_texture = 0;
  GLuint occluder_vao = 0, occluder_vbo = 0, occluder_ebo = 0;
  GLsizei occluder_indices = 0;
  GLuint box_vao = 0, box_vbo = 0;
  std::vector<GLuint> queries;  // visible, then total, per camera of a batch

  int batch_size() const { return tiles_per_row * tiles_per_row; }
  int atlas_side() const { return tiles_per_row * resolution; }
  void upload_box(const Eigen::AlignedBox3d& box);
  void count_batch(const view::Camera* cameras, int n, bool totals, OcclusionCount* out);
  void draw_box(int camera);
};

OcclusionCounter::OcclusionCounter(int resolution) : impl_(std::make_unique<Impl>()) {
  Impl& c = *impl_;
  c.resolution = std::max(resolution, 8);
  c.tiles_per_row = std::clamp(kMaxAtlasSide / c.resolution, 1, kMaxTilesPerRow);
  c.program = detail::link_program(kTileVertex, kDepthOnlyFragment);
  c.instanced = glGetUniformLocation(c.program, "instanced");
  glUseProgram(c.program);
  glUniform1i(glGetUniformLocation(c.program, "view_projections"), 0);
  glUniform1i(glGetUniformLocation(c.program, "tiles_per_row"), c.tiles_per_row);
  glUseProgram(0);

  glGenFramebuffers(1, &c.framebuffer);
  glGenRenderbuffers(1, &c.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, c.depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, c.atlas_side(), c.atlas_side());
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_FRAMEBUFFER, c.framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, c.depth);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (!complete) throw std::runtime_error("render: the occlusion depth atlas is incomplete");

  glGenBuffers(1, &c.matrices_buffer);
  glGenTextures(1, &c.matrices_texture);
  glBindBuffer(GL_TEXTURE_BUFFER, c.matrices_buffer);
  glBufferData(GL_TEXTURE_BUFFER, c.batch_size() * 16 * sizeof(float), nullptr, GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, c.matrices_texture);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, c.matrices_buffer);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);

  glGenVertexArrays(1, &c.occluder_vao);
  glGenBuffers(1, &c.occluder_vbo);
  glGenBuffers(1, &c.occluder_ebo);
  glBindVertexArray(c.occluder_vao);
  glBindBuffer(GL_ARRAY_BUFFER, c.occluder_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, c.occluder_ebo);
  glGenVertexArrays(1, &c.box_vao);
  glGenBuffers(1, &c.box_vbo);
  glBindVertexArray(c.box_vao);
  glBindBuffer(GL_ARRAY_BUFFER, c.box_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(BoxVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribIPointer(1, 1, GL_INT, sizeof(BoxVertex), reinterpret_cast<void*>(offsetof(BoxVertex, camera)));
  glBindVertexArray(0);
  c.queries.resize(2 * c.batch_size());
  glGenQueries(static_cast<GLsizei>(c.queries.size()), c.queries.data());
  detail::check_gl("creating the occlusion counter");
}

OcclusionCounter::~OcclusionCounter() {
  Impl& c = *impl_;
  glDeleteQueries(static_cast<GLsizei>(c.queries.size()), c.queries.data());
  const std::array<GLuint, 4> buffers = {c.matrices_buffer, c.occluder_vbo, c.occluder_ebo, c.box_vbo};
  glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  glDeleteTextures(1, &c.matrices_texture);
  const std::array<GLuint, 2> arrays = {c.occluder_vao, c.box_vao};
  glDeleteVertexArrays(static_cast<GLsizei>(arrays.size()), arrays.data());
  glDeleteRenderbuffers(1, &c.depth);
  glDeleteFramebuffers(1, &c.framebuffer);
  glDeleteProgram(c.program);
}

int OcclusionCounter::resolution() const { return impl_->resolution; }
int OcclusionCounter::batch_size() const { return impl_->batch_size(); }

void OcclusionCounter::set_occluders(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  Impl& c = *impl_;
  const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> positions = V.cast<float>();
  const Eigen::Matrix<unsigned, Eigen::Dynamic, 3, Eigen::RowMajor> indices = F.cast<unsigned>();
  glBindVertexArray(c.occluder_vao);
  glBindBuffer(GL_ARRAY_BUFFER, c.occluder_vbo);
  glBufferData(GL_ARRAY_BUFFER, positions.size() * sizeof(float), positions.data(), GL_STATIC_DRAW);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(unsigned), indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  c.occluder_indices = static_cast<GLsizei>(indices.size());
  detail::check_gl("uploading occluders");
}

// One copy of the box's triangles per camera of a batch.
void OcclusionCounter::Impl::upload_box(const Eigen::AlignedBox3d& box) {
  std::vector<BoxVertex> vertices;
  vertices.reserve(kBoxCorners.size() * batch_size());
  for (int camera = 0; camera < batch_size(); ++camera)
    for (int corner : kBoxCorners) {
      const Eigen::Vector3f p = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)).cast<float>();
      vertices.push_back({p.x(), p.y(), p.z(), camera});
    }
  glBindBuffer(GL_ARRAY_BUFFER, box_vbo);
  glBufferData(GL_ARRAY_BUFFER, vertices.size() * sizeof(BoxVertex), vertices.data(), GL_STREAM_DRAW);
}

void OcclusionCounter::Impl::draw_box(int camera) {
  constexpr auto n = static_cast<GLsizei>(kBoxCorners.size());
  glDrawArrays(GL_TRIANGLES, camera * n, n);
}

void OcclusionCounter::Impl::count_batch(const view::Camera* cameras, int n, bool totals, OcclusionCount* out) {
  std::vector<float> matrices(16 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix4f m = (cameras[i].projection_matrix(1.0) * cameras[i].view_matrix()).cast<float>();
    std::copy(m.data(), m.data() + 16, matrices.begin() + 16 * i);  // column-major: one column per texel
  }
  glBindBuffer(GL_TEXTURE_BUFFER, matrices_buffer);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, matrices.size() * sizeof(float), matrices.data());
  glBindBuffer(GL_TEXTURE_BUFFER, 0);

  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
  // The occluders' depth, every camera at once, both sides of every triangle.
  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_LESS);
  glUniform1i(instanced, 1);
  glBindVertexArray(occluder_vao);
  if (occluder_indices > 0) glDrawElementsInstanced(GL_TRIANGLES, occluder_indices, GL_UNSIGNED_INT, nullptr, n);
  // The box, front faces only (each pixel once), pulled a little towards the eye so that its
  // faces lying on an occluder's surface count as seen; not written into the depth buffer.
  glUniform1i(instanced, 0);
  glBindVertexArray(box_vao);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -4.0f);
  glDepthFunc(GL_LEQUAL);
  for (int i = 0; i < n; ++i) {
    glBeginQuery(GL_SAMPLES_PASSED, queries[2 * i]);
    draw_box(i);
    glEndQuery(GL_SAMPLES_PASSED);
  }
  if (totals) {
    glDepthFunc(GL_ALWAYS);
    for (int i = 0; i < n; ++i) {
      glBeginQuery(GL_SAMPLES_PASSED, queries[2 * i + 1]);
      draw_box(i);
      glEndQuery(GL_SAMPLES_PASSED);
    }
  }
  for (int i = 0; i < n; ++i) {
    GLuint visible = 0, total = 0;
    glGetQueryObjectuiv(queries[2 * i], GL_QUERY_RESULT, &visible);
    if (totals) glGetQueryObjectuiv(queries[2 * i + 1], GL_QUERY_RESULT, &total);
    out[i] = {static_cast<long>(visible), static_cast<long>(total)};
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
}

std::vector<OcclusionCount> OcclusionCounter::count(const Eigen::AlignedBox3d& box,
                                                    const std::vector<view::Camera>& cameras, bool totals) {
  Impl& c = *impl_;
  std::vector<OcclusionCount> counts(cameras.size());
  if (cameras.empty() || box.isEmpty()) return counts;
  GLint previous_framebuffer = 0;
  std::array<GLint, 4> previous_viewport{};
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_framebuffer);
  glGetIntegerv(GL_VIEWPORT, previous_viewport.data());

  glBindFramebuffer(GL_FRAMEBUFFER, c.framebuffer);
  glViewport(0, 0, c.atlas_side(), c.atlas_side());
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  for (int k = 0; k < 4; ++k) glEnable(GL_CLIP_DISTANCE0 + k);
  glUseProgram(c.program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, c.matrices_texture);
  c.upload_box(box);
  const int total = static_cast<int>(cameras.size());
  for (int first = 0; first < total; first += c.batch_size())
    c.count_batch(cameras.data() + first, std::min(c.batch_size(), total - first), totals, counts.data() + first);

  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  for (int k = 0; k < 4; ++k) glDisable(GL_CLIP_DISTANCE0 + k);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);
  detail::check_gl("counting occluded pixels");
  return counts;
}

}  // namespace reconfig::render
