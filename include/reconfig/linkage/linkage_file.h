#pragma once
/// @file
/// Reading and writing "reconfig-linkage" version 1 files (FORMATS.md), with validation.

#include <filesystem>
#include <string>

#include "reconfig/linkage/linkage.h"

namespace reconfig::linkage {

/// Parses and validates a linkage from JSON text.
///
/// Checks: format and version; every joint has a unique non-empty name and a position
/// [x, y] with |x|, |y| ≤ 1e12; every link lists two or more distinct known joints at distinct
/// positions; every joint that is not fixed lies on a link; the motor's center is fixed,
/// its joint is not, and a link (the crank) carries both; tracking points name known joints.
/// It does not check that the linkage is fully constrained (see order_joints).
/// @param text  the JSON document
/// @param file  the file name used in error messages (may be empty)
/// @throws reconfig::InputError naming the JSON path, e.g. `links[2][1]: unknown joint "Q"`
Linkage parse_linkage(const std::string& text, const std::string& file = "");

/// Reads, parses and validates a linkage file, and checks that it is fully constrained
/// (order_joints), not singular in its initial configuration (SymbolicKinematics), and not
/// over-constrained: no link distance would have to change as the motor turns.
/// @throws reconfig::InputError naming the file and the JSON path
Linkage read_linkage(const std::filesystem::path& path);

/// The checks read_linkage adds to parse_linkage: fully constrained (order_joints), not
/// singular in the initial configuration, not over-constrained. For linkages that come from
/// elsewhere (e.g. inline in a scene file).
/// @throws reconfig::InputError (without a file) naming the JSON path or the joints
void check_linkage(const Linkage& linkage);

/// The linkage as "reconfig-linkage" version 1 JSON text (pretty-printed). Round-trips
/// through parse_linkage exactly (positions are printed with 17 significant digits).
std::string linkage_to_json(const Linkage& linkage);

/// Writes linkage_to_json to `path`. @throws reconfig::InputError if it cannot be written
void write_linkage(const Linkage& linkage, const std::filesystem::path& path);

}  // namespace reconfig::linkage
