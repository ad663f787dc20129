#include "reconfig/motion/key_error.h"

#include <utility>

namespace reconfig::motion {

namespace {
std::string describe(std::size_t key, const std::string& field, const std::string& message) {
  std::string s = "key " + std::to_string(key);
  if (!field.empty()) s += " (" + field + ")";
  return s + ": " + message;
}
}  // namespace

KeyError::KeyError(std::size_t key, std::string field, std::string message)
    : std::invalid_argument(describe(key, field, message)),
      key_(key),
      field_(std::move(field)),
      message_(std::move(message)) {}

}  // namespace reconfig::motion
