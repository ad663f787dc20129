#pragma once
/// @file
/// Sorting the vertex or face numbers a query found: a bitmap over the numbers is cheaper than
/// a comparison sort when they are dense (a tool's box holds a tenth of a mesh).

#include <vector>

namespace reconfig::sculpt::detail {

/// Sorts `ids` (each in [0, bound)) ascending and drops duplicates: by a bitmap of `bound`
/// bits when there are enough ids for it to pay, else by `std::sort`.
void sort_unique(std::vector<int>& ids, int bound);

}  // namespace reconfig::sculpt::detail
