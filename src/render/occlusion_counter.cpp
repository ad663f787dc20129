#include "reconfig/render/occlusion_counter.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>

#include "detail/gl_program.h"

namespace reconfig::render {
namespace {

// Camera `gl_InstanceID` of the batch (occluders: one instance per camera), or the vertex's
// own `box_camera` (boxes: one copy per camera, all drawn at once), draws into its own tile
// of the atlas. Its clip coordinates are clipped (gl_ClipDistance) to the rectangle the box
// covers in its image and to the box's far side, then scaled into the tile: an occluder
// outside that rectangle or behind the box hides none of it. Each camera has 6 texels of a
// buffer texture: the columns of its view-projection matrix, the rectangle (x min, x max,
// y min, y max in normalized device coordinates), the clip w of the box's far side and the
// index of its tile.
constexpr const char* kTileVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in int box_camera;
uniform samplerBuffer cameras;
uniform int instanced;
uniform int tiles_per_row;
out float gl_ClipDistance[5];
void main() {
  int camera = instanced != 0 ? gl_InstanceID : box_camera;
  int texel = 6 * camera;
  mat4 m = mat4(texelFetch(cameras, texel), texelFetch(cameras, texel + 1), texelFetch(cameras, texel + 2),
                texelFetch(cameras, texel + 3));
  vec4 rectangle = texelFetch(cameras, texel + 4);
  vec4 far_w_tile = texelFetch(cameras, texel + 5);
  float far_w = far_w_tile.x;
  int tile_index = int(far_w_tile.y);
  vec4 clip = m * vec4(position, 1.0);
  gl_ClipDistance[0] = clip.x - rectangle.x * clip.w;
  gl_ClipDistance[1] = rectangle.y * clip.w - clip.x;
  gl_ClipDistance[2] = clip.y - rectangle.z * clip.w;
  gl_ClipDistance[3] = rectangle.w * clip.w - clip.y;
  gl_ClipDistance[4] = far_w - clip.w;
  float k = float(tiles_per_row);
  vec2 tile = vec2(float(tile_index % tiles_per_row), float(tile_index / tiles_per_row));
  vec2 offset = (2.0 * tile + 1.0) / k - 1.0;
  gl_Position = vec4(clip.xy / k + clip.w * offset, clip.z, clip.w);
}
)";

// Marks the pixels it covers; the color mask picks the channel (red: visible, green: total).
constexpr const char* kMarkFragment = R"(#version 330 core
out vec4 color;
void main() { color = vec4(1.0); }
)";

constexpr int kClipDistances = 5;
constexpr int kTexelsPerCamera = 6;

// The 12 outward (counter-clockwise) triangles of a box, as 36 corner indices of
// Eigen::AlignedBox3d::corner (bit 0: x max, bit 1: y max, bit 2: z max).
constexpr std::array<int, 36> kBoxCorners = {0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                                             2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5};

constexpr int kMaxAtlasSide = 1024;
constexpr int kMaxTilesPerRow = 16;

struct BoxVertex {
  float x, y, z;
  GLint camera;
};

// The texels of one camera drawn into `tile`: its view-projection matrix, then the rectangle
// of its image that holds the box and the clip w just behind the box, both with a margin (two
// pixels; 0.1 %) so that clipping there changes no pixel of the box. A box reaching behind
// the eye keeps the whole image and the camera's far plane.
void camera_texels(const view::Camera& camera, int tile, const Eigen::AlignedBox3d& box, int resolution, float* out) {
  const Eigen::Matrix4d m = camera.projection_matrix(1.0) * camera.view_matrix();
  const Eigen::Matrix4f mf = m.cast<float>();
  std::copy(mf.data(), mf.data() + 16, out);  // column-major: one column per texel
  Eigen::Vector2d low(1, 1), high(-1, -1);
  double far_w = 0;
  bool in_front = true;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector4d clip = m * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)).homogeneous();
    in_front = in_front && clip.w() > 0;
    if (!in_front) break;
    const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
    low = low.cwiseMin(ndc);
    high = high.cwiseMax(ndc);
    far_w = std::max(far_w, clip.w());
  }
  const double margin = 4.0 / resolution;
  if (!in_front) {
    low.setConstant(-1);
    high.setConstant(1);
    far_w = camera.far_plane;
  }
  low = (low.array() - margin).max(-1.0);
  high = (high.array() + margin).min(1.0);
  const std::array<float, 8> rest = {static_cast<float>(low.x()),  static_cast<float>(high.x()),
                                     static_cast<float>(low.y()),  static_cast<float>(high.y()),
                                     static_cast<float>(far_w * 1.001), static_cast<float>(tile), 0, 0};
  std::copy(rest.begin(), rest.end(), out + 16);
}

}  // namespace

struct OcclusionCounter::Impl {
  int resolution = 64, tiles_per_row = 1;
  GLuint program = 0;
  GLint instanced = -1;
  GLuint framebuffer = 0, depth = 0, marks = 0;
  GLuint cameras_buffer = 0, cameras_texture = 0;
  GLuint occluder_vao = 0, occluder_vbo = 0, occluder_ebo = 0;
  GLsizei occluder_indices = 0;
  GLuint box_vao = 0, box_vbo = 0;
  std::vector<std::uint8_t> pixels;  // the marks read back, two bytes a pixel

  int batch_size() const { return tiles_per_row * tiles_per_row; }
  int atlas_side() const { return tiles_per_row * resolution; }
  int tile_rows(const std::vector<int>& batch) const;
  void upload_box(const Eigen::AlignedBox3d& box);
  void upload_cameras(const std::vector<view::Camera>& cameras, const std::vector<int>& batch,
                      const Eigen::AlignedBox3d& box);
  void count_batch(const std::vector<view::Camera>& cameras, const std::vector<int>& batch,
                   const Eigen::AlignedBox3d& box, bool visible, bool totals, std::vector<OcclusionCount>& out);
  void draw_occluders(int n);
  void draw_boxes(int n, bool occluded);
  void read_marks(const std::vector<int>& batch, std::vector<OcclusionCount>& out);
};

OcclusionCounter::OcclusionCounter(int resolution) : impl_(std::make_unique<Impl>()) {
  Impl& c = *impl_;
  c.resolution = std::max(resolution, 8);
  c.tiles_per_row = std::clamp(kMaxAtlasSide / c.resolution, 1, kMaxTilesPerRow);
  c.program = detail::link_program(kTileVertex, kMarkFragment);
  c.instanced = glGetUniformLocation(c.program, "instanced");
  glUseProgram(c.program);
  glUniform1i(glGetUniformLocation(c.program, "cameras"), 0);
  glUniform1i(glGetUniformLocation(c.program, "tiles_per_row"), c.tiles_per_row);
  glUseProgram(0);

  glGenFramebuffers(1, &c.framebuffer);
  glGenRenderbuffers(1, &c.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, c.depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, c.atlas_side(), c.atlas_side());
  glGenRenderbuffers(1, &c.marks);
  glBindRenderbuffer(GL_RENDERBUFFER, c.marks);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RG8, c.atlas_side(), c.atlas_side());
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_FRAMEBUFFER, c.framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, c.depth);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, c.marks);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (!complete) throw std::runtime_error("render: the occlusion atlas is incomplete");

  glGenBuffers(1, &c.cameras_buffer);
  glGenTextures(1, &c.cameras_texture);
  glBindBuffer(GL_TEXTURE_BUFFER, c.cameras_buffer);
  glBufferData(GL_TEXTURE_BUFFER, c.batch_size() * kTexelsPerCamera * 4 * sizeof(float), nullptr, GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, c.cameras_texture);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, c.cameras_buffer);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);

  detail::make_indexed_positions_vao(c.occluder_vao, c.occluder_vbo, c.occluder_ebo);
  glGenVertexArrays(1, &c.box_vao);
  glGenBuffers(1, &c.box_vbo);
  glBindVertexArray(c.box_vao);
  glBindBuffer(GL_ARRAY_BUFFER, c.box_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(BoxVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribIPointer(1, 1, GL_INT, sizeof(BoxVertex), reinterpret_cast<void*>(offsetof(BoxVertex, camera)));
  glBindVertexArray(0);
  detail::check_gl("creating the occlusion counter");
}

OcclusionCounter::~OcclusionCounter() {
  Impl& c = *impl_;
  const std::array<GLuint, 4> buffers = {c.cameras_buffer, c.occluder_vbo, c.occluder_ebo, c.box_vbo};
  glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  glDeleteTextures(1, &c.cameras_texture);
  const std::array<GLuint, 2> arrays = {c.occluder_vao, c.box_vao};
  glDeleteVertexArrays(static_cast<GLsizei>(arrays.size()), arrays.data());
  const std::array<GLuint, 2> renderbuffers = {c.depth, c.marks};
  glDeleteRenderbuffers(static_cast<GLsizei>(renderbuffers.size()), renderbuffers.data());
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

// The texels of the cameras of `batch` (indices into `cameras`, each with its own tile).
void OcclusionCounter::Impl::upload_cameras(const std::vector<view::Camera>& cameras, const std::vector<int>& batch,
                                            const Eigen::AlignedBox3d& box) {
  std::vector<float> texels(kTexelsPerCamera * 4 * batch.size());
  for (std::size_t k = 0; k < batch.size(); ++k)
    camera_texels(cameras[batch[k]], batch[k] % batch_size(), box, resolution,
                  texels.data() + kTexelsPerCamera * 4 * k);
  glBindBuffer(GL_TEXTURE_BUFFER, cameras_buffer);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, texels.size() * sizeof(float), texels.data());
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

// The occluders' depth, every camera at once, both sides of every triangle, no marks.
void OcclusionCounter::Impl::draw_occluders(int n) {
  if (occluder_indices == 0) return;
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glUniform1i(instanced, 1);
  glBindVertexArray(occluder_vao);
  glDrawElementsInstanced(GL_TRIANGLES, occluder_indices, GL_UNSIGNED_INT, nullptr, n);
}

// The box of every camera, front faces only (each pixel once). Occluded: marks red where no
// occluder is in front, the box pulled a little towards the eye so that its faces lying on an
// occluder's surface count as seen; else marks green wherever it covers. Writes no depth.
void OcclusionCounter::Impl::draw_boxes(int n, bool occluded) {
  glColorMask(occluded, !occluded, GL_FALSE, GL_FALSE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glDepthMask(GL_FALSE);
  glDepthFunc(occluded ? GL_LEQUAL : GL_ALWAYS);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -4.0f);
  glUniform1i(instanced, 0);
  glBindVertexArray(box_vao);
  glDrawArrays(GL_TRIANGLES, 0, n * static_cast<GLsizei>(kBoxCorners.size()));
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// The rows of tiles up to the last one that `batch` uses.
int OcclusionCounter::Impl::tile_rows(const std::vector<int>& batch) const {
  int last = 0;
  for (int camera : batch) last = std::max(last, camera % batch_size());
  return last / tiles_per_row + 1;
}

// Reads back the tile rows in use and counts the marks in the tile of each camera of `batch`.
void OcclusionCounter::Impl::read_marks(const std::vector<int>& batch, std::vector<OcclusionCount>& out) {
  const int width = atlas_side(), height = tile_rows(batch) * resolution;
  pixels.resize(2 * static_cast<std::size_t>(width) * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RG, GL_UNSIGNED_BYTE, pixels.data());
  for (int camera : batch) {
    const int tile = camera % batch_size(), x0 = (tile % tiles_per_row) * resolution,
              y0 = (tile / tiles_per_row) * resolution;
    OcclusionCount count;
    for (int y = y0; y < y0 + resolution; ++y) {
      const std::uint8_t* p = pixels.data() + 2 * (static_cast<std::size_t>(width) * y + x0);
      for (int x = 0; x < resolution; ++x, p += 2) {
        count.visible += p[0] != 0;
        count.total += p[1] != 0;
      }
    }
    out[camera] = count;
  }
}

// Counts the cameras of `batch` (indices into `cameras` whose tiles differ) into `out`.
void OcclusionCounter::Impl::count_batch(const std::vector<view::Camera>& cameras, const std::vector<int>& batch,
                                         const Eigen::AlignedBox3d& box, bool visible, bool totals,
                                         std::vector<OcclusionCount>& out) {
  const int n = static_cast<int>(batch.size());
  upload_cameras(cameras, batch, box);
  glEnable(GL_SCISSOR_TEST);  // only the tile rows in use
  glScissor(0, 0, atlas_side(), tile_rows(batch) * resolution);
  glClearColor(0, 0, 0, 0);
  glDepthMask(GL_TRUE);
  glClear(visible ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  if (visible) {
    draw_occluders(n);
    draw_boxes(n, true);
  }
  if (totals) draw_boxes(n, false);
  read_marks(batch, out);
}

namespace {

// `which` split into batches, each camera into the first batch that does not hold its tile
// yet (camera index modulo the batch size); every camera in order make full batches.
std::vector<std::vector<int>> tile_batches(const std::vector<int>& which, int batch_size) {
  std::vector<std::vector<int>> batches;
  std::vector<std::vector<bool>> used;
  for (int camera : which) {
    const int tile = camera % batch_size;
    std::size_t b = 0;
    while (b < batches.size() && used[b][tile]) ++b;
    if (b == batches.size()) {
      batches.emplace_back();
      used.emplace_back(batch_size, false);
    }
    batches[b].push_back(camera);
    used[b][tile] = true;
  }
  return batches;
}

std::vector<int> all_of(const std::vector<view::Camera>& cameras) {
  std::vector<int> which(cameras.size());
  std::iota(which.begin(), which.end(), 0);
  return which;
}

}  // namespace

std::vector<OcclusionCount> OcclusionCounter::count(const Eigen::AlignedBox3d& box,
                                                    const std::vector<view::Camera>& cameras, bool totals) {
  return count_pixels(box, cameras, all_of(cameras), true, totals);
}

std::vector<OcclusionCount> OcclusionCounter::count_selected(const Eigen::AlignedBox3d& box,
                                                             const std::vector<view::Camera>& cameras,
                                                             const std::vector<int>& which, bool totals) {
  const std::vector<OcclusionCount> counts = count_pixels(box, cameras, which, true, totals);
  std::vector<OcclusionCount> chosen(which.size());
  std::transform(which.begin(), which.end(), chosen.begin(), [&](int camera) { return counts[camera]; });
  return chosen;
}

std::vector<long> OcclusionCounter::coverage(const Eigen::AlignedBox3d& box, const std::vector<view::Camera>& cameras) {
  const std::vector<OcclusionCount> counts = count_pixels(box, cameras, all_of(cameras), false, true);
  std::vector<long> totals(counts.size());
  std::transform(counts.begin(), counts.end(), totals.begin(), [](const OcclusionCount& c) { return c.total; });
  return totals;
}

std::vector<OcclusionCount> OcclusionCounter::count_pixels(const Eigen::AlignedBox3d& box,
                                                           const std::vector<view::Camera>& cameras,
                                                           const std::vector<int>& which, bool visible, bool totals) {
  Impl& c = *impl_;
  std::vector<OcclusionCount> counts(cameras.size());
  if (which.empty() || box.isEmpty()) return counts;
  GLint previous_framebuffer = 0, previous_pack_alignment = 4;
  std::array<GLint, 4> previous_viewport{};
  std::array<GLfloat, 4> previous_clear_color{};
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_framebuffer);
  glGetIntegerv(GL_VIEWPORT, previous_viewport.data());
  glGetIntegerv(GL_PACK_ALIGNMENT, &previous_pack_alignment);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, previous_clear_color.data());

  glBindFramebuffer(GL_FRAMEBUFFER, c.framebuffer);
  glViewport(0, 0, c.atlas_side(), c.atlas_side());
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  for (int k = 0; k < kClipDistances; ++k) glEnable(GL_CLIP_DISTANCE0 + k);
  glUseProgram(c.program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, c.cameras_texture);
  c.upload_box(box);
  for (const std::vector<int>& batch : tile_batches(which, c.batch_size()))
    c.count_batch(cameras, batch, box, visible, totals, counts);

  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  for (int k = 0; k < kClipDistances; ++k) glDisable(GL_CLIP_DISTANCE0 + k);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);
  glPixelStorei(GL_PACK_ALIGNMENT, previous_pack_alignment);
  glClearColor(previous_clear_color[0], previous_clear_color[1], previous_clear_color[2], previous_clear_color[3]);
  detail::check_gl("counting occluded pixels");
  return counts;
}

}  // namespace reconfig::render
