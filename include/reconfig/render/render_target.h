#pragma once
/// @file
/// An offscreen framebuffer whose color lives in a texture: the studio draws its viewport into
/// one and shows the texture inside the UI, and draws whole headless frames into another.

#include "reconfig/render/image.h"

namespace reconfig::render {

/// A framebuffer object with an RGBA8 color texture and a depth-stencil buffer. Needs a current
/// OpenGL 3.3 context for its whole life.
class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  /// (Re)allocates the buffers when the size changes. Sizes below 1 become 1.
  void resize(int width, int height);
  /// Binds it as the framebuffer drawn into and sets the viewport to all of it.
  void bind() const;
  /// Binds the default framebuffer (the window's, if any) again.
  static void unbind();

  /// The color texture's GL name (0 before the first `resize`).
  unsigned texture() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }

  /// The current contents, top row first.
  Image read_pixels() const;

 private:
  void release();
  unsigned framebuffer_ = 0, texture_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

/// Reads the bound framebuffer's pixels in [0, width) × [0, height) as an image, top row first.
Image read_bound_framebuffer(int width, int height);

}  // namespace reconfig::render
