#include "sculpt/detail/sort_unique.h"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace reconfig::sculpt::detail {
namespace {

/// A bitmap costs about one operation per 64 numbers of the range, a sort about log₂ n per id.
constexpr int kBitsPerSortedId = 64 * 8;

}  // namespace

void sort_unique(std::vector<int>& ids, int bound) {
  if (static_cast<long long>(ids.size()) * kBitsPerSortedId < bound) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return;
  }
  std::vector<std::uint64_t> bits((bound + 63) / 64, 0);
  for (int id : ids) bits[id >> 6] |= std::uint64_t{1} << (id & 63);
  ids.clear();
  for (std::size_t word = 0; word < bits.size(); ++word)
    for (std::uint64_t w = bits[word]; w != 0; w &= w - 1)
      ids.push_back(static_cast<int>(word * 64 + std::countr_zero(w)));
}

}  // namespace reconfig::sculpt::detail
