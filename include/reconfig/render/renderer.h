#pragma once
/// @file
/// The OpenGL 3.3 core renderer: shaded meshes (two-light Lambert + ambient, flat normals),
/// selection highlight, ghosts, transparent pulsating boxes with edges, lines, arrows and a
/// ground grid, into a multisampled offscreen framebuffer read back as RGBA.

#include <memory>

#include "reconfig/render/draw_list.h"
#include "reconfig/render/image.h"
#include "reconfig/view/camera.h"

namespace reconfig::render {

struct RendererOptions {
  int samples = 4;  ///< MSAA samples (clamped to what the driver offers; 0 or 1: none)
};

/// Needs a current OpenGL 3.3 core context (e.g. `EglContext`) for its whole life, on the
/// thread that created it. Throws `std::runtime_error` on shader or framebuffer failures.
class Renderer {
 public:
  explicit Renderer(const RendererOptions& options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Draws `list` seen by `camera` into an offscreen width × height framebuffer and reads
  /// it back.
  Image render(const DrawList& list, const view::Camera& camera, int width, int height);

  /// Draws `list` into the currently bound framebuffer (a window's), viewport width × height.
  void draw(const DrawList& list, const view::Camera& camera, int width, int height);

  /// MSAA samples actually used.
  int samples() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reconfig::render
