#include "sculpt/detail/sort_unique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace reconfig::sculpt::detail {
namespace {

TEST(SortUnique, AgreesWithSortAndUniqueFromSparseToDenseIds) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 400; ++trial) {
    const int bound = 1 + static_cast<int>(random() % 20000);
    const int count = static_cast<int>(random() % (trial % 4 == 0 ? 50 : 2 * bound + 1));  // both ways of sorting
    std::uniform_int_distribution<int> id(0, bound - 1);
    std::vector<int> ids(count);
    for (int& i : ids) i = id(random);
    if (trial % 3 == 0) ids.push_back(bound - 1);  // the last word's last bits
    std::vector<int> expected = ids;
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    sort_unique(ids, bound);
    ASSERT_EQ(ids, expected) << "trial " << trial << ", bound " << bound << ", " << count << " ids";
  }
}

}  // namespace
}  // namespace reconfig::sculpt::detail
