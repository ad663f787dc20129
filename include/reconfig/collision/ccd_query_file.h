#pragma once
/// @file
/// Reading continuous-collision queries in the public CCD benchmark format (Wang et al. 2021;
/// FORMATS.md, `reconfig ccd-queries`).
///
/// A file holds 8 rows per query, each `x_num,x_den,y_num,y_den,z_num,z_den,truth`: one point
/// as three exact rationals (integers of any size, optional sign, decimal digits only) and the
/// expected answer (0 or 1). Vertex–face rows are `v_t0, f0_t0, f1_t0, f2_t0, v_t1, f0_t1,
/// f1_t1, f2_t1`; edge–edge rows `ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1,
/// eb1_t1`. Blank lines are skipped; line numbers in errors count every line (from 1).
///
/// Coordinates are parsed exactly (GMP rationals) and converted to the nearest-or-adjacent
/// double; the conversion error is measured exactly and reported per query, so a conservative
/// test can absorb it (`PrimitiveCcdOptions::separation`): queries whose rationals are doubles
/// (all of the public benchmark) are answered for exactly the input.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace reconfig::collision {

/// One query of a CCD benchmark file.
struct CcdQuery {
  std::array<Eigen::Vector3d, 8> points;  ///< the 8 rows, as doubles (file order)
  /// Largest |exact rational − double| over the query's 24 coordinates, rounded up
  /// (0 when every coordinate is a double).
  double conversion_error = 0;
  bool truth = false;  ///< the file's truth column of the query's first row (nonzero = 1)
  int first_line = 0;  ///< line number of the query's first row
};

/// Parses queries from `in`.
/// @param in         the file's content
/// @param file_name  used in errors
/// @throws InputError naming `file_name` and `line <n>` for a row with a column count other
///   than 7, a field that is not an integer, a zero denominator, or a coordinate of magnitude
///   2^1000 or more; and (naming the last line) when the number of rows is not a multiple of 8.
std::vector<CcdQuery> parse_ccd_queries(std::istream& in, const std::string& file_name);

/// Reads and parses the file at `path` (see `parse_ccd_queries`).
/// @throws InputError naming `path` if it cannot be opened, or as `parse_ccd_queries`
std::vector<CcdQuery> read_ccd_queries(const std::filesystem::path& path);

}  // namespace reconfig::collision
