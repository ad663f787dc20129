#include "scene/detail/json_cursor.h"

#include <cmath>
#include <limits>
#include <fmt/format.h>

namespace reconfig::scene::detail {
namespace {

const char* type_name(const nlohmann::json& v) { return v.type_name(); }

}  // namespace

JsonCursor JsonCursor::operator[](const std::string& key) const {
  if (!value_.is_object()) fail(fmt::format("expected an object, found {}", type_name(value_)));
  const std::string child = path_.empty() ? key : path_ + "." + key;
  const auto it = value_.find(key);
  if (it == value_.end()) throw InputError("", path_.empty() ? key : child, "missing required field");
  return {*it, child};
}

JsonCursor JsonCursor::operator[](std::size_t i) const {
  return {value_.at(i), fmt::format("{}[{}]", path_, i)};
}

void JsonCursor::expect_object(std::initializer_list<const char*> allowed) const {
  if (!value_.is_object()) fail(fmt::format("expected an object, found {}", type_name(value_)));
  for (const auto& item : value_.items()) {
    bool known = false;
    for (const char* name : allowed) known = known || item.key() == name;
    if (!known) {
      std::string list;
      for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      throw InputError("", path_.empty() ? item.key() : path_ + "." + item.key(),
                       fmt::format("unknown field (expected one of: {})", list));
    }
  }
}

std::size_t JsonCursor::expect_array(std::ptrdiff_t size) const {
  if (!value_.is_array()) fail(fmt::format("expected an array, found {}", type_name(value_)));
  if (size >= 0 && value_.size() != static_cast<std::size_t>(size))
    fail(fmt::format("expected {} elements, found {}", size, value_.size()));
  return value_.size();
}

std::string JsonCursor::as_string() const {
  if (!value_.is_string()) fail(fmt::format("expected a string, found {}", type_name(value_)));
  return value_.get<std::string>();
}

std::string JsonCursor::as_name() const {
  std::string name = as_string();
  if (name.empty()) fail("name must not be empty");
  for (const char c : name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) fail("a name must not contain control characters");
  return name;
}

double JsonCursor::as_number() const {
  if (!value_.is_number()) fail(fmt::format("expected a number, found {}", type_name(value_)));
  const double x = value_.get<double>();
  if (!std::isfinite(x)) fail("number is not finite");
  return x;
}

double JsonCursor::as_positive() const {
  const double x = as_number();
  if (!(x > 0)) fail(fmt::format("must be positive, found {}", x));
  return x;
}

double JsonCursor::as_length() const {
  const double x = as_positive();
  if (x > kMaxPrimitiveSize) fail(fmt::format("must be at most {:g}, found {:g}", kMaxPrimitiveSize, x));
  return x;
}

bool JsonCursor::as_bool() const {
  if (!value_.is_boolean()) fail(fmt::format("expected true or false, found {}", type_name(value_)));
  return value_.get<bool>();
}

Eigen::Vector3d JsonCursor::as_vector3() const {
  expect_array(3);
  return {(*this)[0].as_number(), (*this)[1].as_number(), (*this)[2].as_number()};
}

Eigen::Quaterniond JsonCursor::as_unit_quaternion() const {
  expect_array(4);
  Eigen::Quaterniond q((*this)[0].as_number(), (*this)[1].as_number(), (*this)[2].as_number(),
                       (*this)[3].as_number());
  const double norm = q.norm();
  if (std::abs(norm - 1.0) > 1e-3)
    fail(fmt::format("quaternion [w, x, y, z] must have unit length, found length {:.6g}", norm));
  // Normalize once: a quaternion written by this program is already unit to the last bit,
  // and normalizing it again could change that bit (saving must round-trip exactly).
  if (std::abs(norm - 1.0) > 4 * std::numeric_limits<double>::epsilon()) q.normalize();
  return q;
}

}  // namespace reconfig::scene::detail
