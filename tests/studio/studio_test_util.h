#pragma once
/// @file
/// A headless studio on a private copy of the bench-table example.

#include <filesystem>

#include "frontend.h"
#include "reconfig/view/picking.h"
#include "support/test_data.h"

namespace reconfig::studio {

/// Copies examples/bench-table into a fresh temporary folder; returns its scene file.
inline std::filesystem::path bench_table_copy() {
  const std::filesystem::path dir = testing::fresh_temp_dir() / "bench-table";
  std::filesystem::copy(testing::source_dir() / "examples" / "bench-table", dir,
                        std::filesystem::copy_options::recursive);
  return dir / "scene.json";
}

/// A screen point of the studio's viewport where part `part` is the nearest thing under the
/// mouse at the current time (a face center whose pick ray hits this part first).
inline std::optional<ImVec2> visible_point(Studio& studio, int part) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const Layout& layout = studio.layout();
  const int width = static_cast<int>(layout.viewport_max.x - layout.viewport_min.x);
  const int height = static_cast<int>(layout.viewport_max.y - layout.viewport_min.y);
  const auto posed = [&](int p) { return scene.posed_vertices(studio.active_transition(), p, studio.time()); };
  const Eigen::MatrixX3d V = posed(part);
  const Eigen::MatrixX3i& F = scene.parts[part].mesh.F;
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d center = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))).transpose() / 3;
    const auto pixel = view::project_to_pixel(studio.camera(), width, height, center);
    if (!pixel || pixel->pixel.x() < 5 || pixel->pixel.y() < 5 || pixel->pixel.x() > width - 5 ||
        pixel->pixel.y() > height - 5)
      continue;
    const view::Ray ray = view::ray_from_pixel(studio.camera(), width, height, pixel->pixel.x(), pixel->pixel.y());
    int nearest = -1;
    double nearest_s = INFINITY;
    for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
      if (const auto hit = view::ray_mesh(ray, posed(p), scene.parts[p].mesh.F); hit && hit->s < nearest_s) {
        nearest_s = hit->s;
        nearest = p;
      }
    if (nearest == part)
      return ImVec2{layout.viewport_min.x + static_cast<float>(pixel->pixel.x()),
                    layout.viewport_min.y + static_cast<float>(pixel->pixel.y())};
  }
  return std::nullopt;
}

/// Pixel color distance (sum of absolute RGB differences).
inline int color_distance(const std::array<std::uint8_t, 4>& a, const std::array<std::uint8_t, 4>& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

/// Whether a pixel is clearly red (collision bands and boxes).
inline bool reddish(const std::array<std::uint8_t, 4>& p) { return p[0] > 150 && p[0] > p[1] + 60 && p[0] > p[2] + 60; }

}  // namespace reconfig::studio
