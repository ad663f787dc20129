#pragma once
// A read position inside a JSON document that knows its own path, so every error names the
// element it is about (`transitions[0].tracks.seat.rotation[1].time`).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>

#include "reconfig/common/input_error.h"

namespace reconfig::scene::detail {

/// The largest size of a box, cylinder or sphere (docs/file-formats.md, "Limits").
inline constexpr double kMaxPrimitiveSize = 1e12;

class JsonCursor {
 public:
  JsonCursor(const nlohmann::json& value, std::string path) : value_(value), path_(std::move(path)) {}

  const nlohmann::json& value() const { return value_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& message) const { throw InputError("", path_, message); }

  bool has(const std::string& key) const { return value_.is_object() && value_.contains(key); }
  /// The member `key` of an object (error if missing).
  JsonCursor operator[](const std::string& key) const;
  /// Element `i` of an array.
  JsonCursor operator[](std::size_t i) const;

  /// Requires an object whose keys are all in `allowed` (catches misspelled fields).
  void expect_object(std::initializer_list<const char*> allowed) const;
  /// Requires an array (optionally of exactly `size` elements).
  std::size_t expect_array(std::ptrdiff_t size = -1) const;

  std::string as_string() const;
  /// A non-empty name without control characters (the tools print names).
  std::string as_name() const;
  double as_number() const;  ///< finite number
  double as_positive() const;
  /// A primitive's size: positive and at most `kMaxPrimitiveSize`.
  double as_length() const;
  bool as_bool() const;
  Eigen::Vector3d as_vector3() const;
  /// `[w, x, y, z]`, unit within 1e-3, returned normalized.
  Eigen::Quaterniond as_unit_quaternion() const;

 private:
  const nlohmann::json& value_;
  std::string path_;
};

}  // namespace reconfig::scene::detail
