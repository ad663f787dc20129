#pragma once
// The render tests draw with a real OpenGL context: Mesa's EGL surfaceless platform
// (llvmpipe), no display. If the context cannot be made, every test fails saying why.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "reconfig/render/egl_context.h"
#include "reconfig/render/renderer.h"
#include "reconfig/view/picking.h"

namespace reconfig::render::testing {

class RenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (context_) return;
    try {
      context_ = std::make_unique<EglContext>();
      renderer_ = std::make_unique<Renderer>();
    } catch (const std::exception& error) {
      error_ = error.what();
    }
  }
  void SetUp() override {
    if (!context_ || !renderer_) GTEST_FAIL() << "no headless OpenGL context: " << error_;
    context_->make_current();
  }
  Renderer& renderer() { return *renderer_; }

  static inline std::unique_ptr<EglContext> context_;
  static inline std::unique_ptr<Renderer> renderer_;
  static inline std::string error_;
};

inline int color_distance(const std::array<std::uint8_t, 4>& a, const std::array<std::uint8_t, 4>& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

/// Whether the ray through pixel (x, y) or one of its 8 neighbours hits the mesh: changed
/// pixels on a silhouette are antialiased, so they may lie just outside it.
inline bool hits_near(const view::Camera& camera, int width, int height, int x, int y, const Eigen::MatrixX3d& V,
                      const Eigen::MatrixX3i& F) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (view::ray_mesh(view::ray_from_pixel(camera, width, height, x + 0.5 + dx, y + 0.5 + dy), V, F)) return true;
  return false;
}

}  // namespace reconfig::render::testing
