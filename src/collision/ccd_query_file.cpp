#include "reconfig/collision/ccd_query_file.h"

#include <gmpxx.h>

#include <cmath>
#include <fstream>
#include <string_view>

#include "reconfig/common/input_error.h"
#include "reconfig/common/read_input_file.h"

namespace reconfig::collision {
namespace {

std::string_view trim(std::string_view text) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return text;
}

/// An optionally signed decimal integer, exactly.
bool parse_integer(std::string_view text, mpz_class& value) {
  text = trim(text);
  std::string digits(text);
  if (!digits.empty() && digits[0] == '+') digits.erase(0, 1);
  const size_t first = !digits.empty() && digits[0] == '-' ? 1 : 0;
  if (digits.size() == first) return false;
  for (size_t i = first; i < digits.size(); ++i)
    if (digits[i] < '0' || digits[i] > '9') return false;
  return value.set_str(digits, 10) == 0;
}

/// The double nearest to q (ties either way), and |q − double| rounded up.
double to_double(const mpq_class& q, double& error) {
  const double truncated = q.get_d();  // rounds toward zero
  mpq_class exact(truncated);
  if (exact == q) {
    error = 0;
    return truncated;
  }
  const double away = std::nextafter(truncated, sgn(q) > 0 ? HUGE_VAL : -HUGE_VAL);
  mpq_class e1 = abs(q - exact), e2 = abs(q - mpq_class(away));
  const bool use_away = std::isfinite(away) && e2 < e1;
  const mpq_class& e = use_away ? e2 : e1;
  error = std::nextafter(e.get_d(), HUGE_VAL);  // get_d truncates: one step up bounds it
  return use_away ? away : truncated;
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
  throw InputError(file, "line " + std::to_string(line), message);
}

}  // namespace

std::vector<CcdQuery> parse_ccd_queries(std::istream& in, const std::string& file_name) {
  static const char* const kFields[7] = {"x numerator", "x denominator", "y numerator", "y denominator",
                                         "z numerator", "z denominator", "truth"};
  std::vector<CcdQuery> queries;
  std::string text;
  int line = 0, rows = 0, last_row_line = 0;
  mpz_class field[7];
  while (std::getline(in, text)) {
    ++line;
    const std::string_view row = trim(text);
    if (row.empty()) continue;
    int count = 0;
    size_t begin = 0;
    while (true) {
      const size_t comma = row.find(',', begin);
      const std::string_view piece = row.substr(begin, comma == std::string_view::npos ? row.npos : comma - begin);
      if (count < 7 && !parse_integer(piece, field[count]))
        fail(file_name, line, std::string(kFields[count]) + " is not an integer: '" + std::string(trim(piece)) + "'");
      ++count;
      if (comma == std::string_view::npos) break;
      begin = comma + 1;
    }
    if (count != 7) fail(file_name, line, "expected 7 comma-separated columns, found " + std::to_string(count));

    const int k = rows % 8;
    if (k == 0) {
      queries.emplace_back();
      queries.back().first_line = line;
      queries.back().truth = field[6] != 0;
    }
    CcdQuery& query = queries.back();
    for (int axis = 0; axis < 3; ++axis) {
      const mpz_class& den = field[2 * axis + 1];
      if (den == 0) fail(file_name, line, std::string(kFields[2 * axis + 1]) + " is zero");
      mpq_class q(field[2 * axis], den);
      q.canonicalize();
      // Checked exactly, before the conversion: beyond the doubles' range it is undefined.
      static const mpq_class kLimit(mpz_class(1) << 1000);
      double error = 0;
      const double x = abs(q) < kLimit ? to_double(q, error) : HUGE_VAL;
      if (!(std::abs(x) < 0x1p1000))
        fail(file_name, line, std::string(1, "xyz"[axis]) + " coordinate is out of range (magnitude 2^1000 or more)");
      query.points[k][axis] = x;
      query.conversion_error = std::max(query.conversion_error, error);
    }
    ++rows;
    last_row_line = line;
  }
  if (rows % 8 != 0)
    fail(file_name, last_row_line,
         std::to_string(rows) + " rows is not a multiple of 8 (a query has 8 rows; the last one is incomplete)");
  return queries;
}

std::vector<CcdQuery> read_ccd_queries(const std::filesystem::path& path) {
  std::istringstream in(read_input_file(path));  // a regular file of at most 1 GiB
  return parse_ccd_queries(in, path.string());
}

}  // namespace reconfig::collision
