#include "geometry/detail/weld_vertices.h"

#include <array>
#include <bit>
#include <cstdint>
#include <unordered_map>

namespace reconfig::geometry::detail {
namespace {

using Key = std::array<std::uint64_t, 3>;

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t x : k) {
      h ^= x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 0xff51afd7ed558ccdull;
    }
    return static_cast<std::size_t>(h ^ (h >> 33));
  }
};

Key key_of(const Eigen::Vector3d& p) {
  // Adding +0.0 turns -0.0 into +0.0 so both weld.
  return {std::bit_cast<std::uint64_t>(p.x() + 0.0), std::bit_cast<std::uint64_t>(p.y() + 0.0),
          std::bit_cast<std::uint64_t>(p.z() + 0.0)};
}

}  // namespace

void weld_vertices(const std::vector<Eigen::Vector3d>& positions, const std::vector<Eigen::Vector3i>& faces,
                   Eigen::MatrixX3d& V, Eigen::MatrixX3i& F) {
  std::vector<char> used(positions.size(), 0);
  for (const auto& face : faces)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(face[k])] = 1;
  std::vector<int> new_index(positions.size(), -1);
  std::unordered_map<Key, int, KeyHash> by_position;
  by_position.reserve(positions.size());
  std::vector<std::size_t> kept;  // index into `positions` of each new vertex
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!used[i]) continue;
    const auto [it, inserted] = by_position.try_emplace(key_of(positions[i]), static_cast<int>(kept.size()));
    if (inserted) kept.push_back(i);
    new_index[i] = it->second;
  }
  V.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = positions[kept[i]].transpose();
  F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) F(static_cast<Eigen::Index>(f), k) = new_index[static_cast<std::size_t>(faces[f][k])];
}

}  // namespace reconfig::geometry::detail
