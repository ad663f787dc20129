#pragma once
/// @file
/// The error a track constructor throws for an invalid keyframe.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace reconfig::motion {

/// An invalid keyframe in a track's key list (non-increasing time, NaN, zero quaternion).
///
/// Derives from `std::invalid_argument` and names the offending key by index and field so
/// a loader can turn it into a JSON path (`...rotation[1].time`). Field names follow the
/// scene file (FORMATS.md): `time`, `point`, `in`, `out`, `quaternion`, `translation`,
/// `rotation`; empty when the whole list is at fault (e.g. no keys at all).
/// `what()` reads `key 1 (time): keyframe times must strictly increase`.
class KeyError : public std::invalid_argument {
 public:
  /// @param key      index of the offending key in the list
  /// @param field    which field of that key (see above), or empty
  /// @param message  what is wrong, lower case, no trailing period
  KeyError(std::size_t key, std::string field, std::string message);

  std::size_t key() const { return key_; }
  const std::string& field() const { return field_; }
  const std::string& message() const { return message_; }

 private:
  std::size_t key_;
  std::string field_;
  std::string message_;
};

}  // namespace reconfig::motion
