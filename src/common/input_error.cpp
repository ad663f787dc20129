#include "reconfig/common/input_error.h"

#include <utility>

namespace reconfig {
namespace {

std::string join(const std::string& file, const std::string& location, const std::string& message) {
  std::string line;
  if (!file.empty()) line += file + ": ";
  if (!location.empty()) line += location + ": ";
  return line + message;
}

}  // namespace

InputError::InputError(std::string file, std::string location, std::string message)
    : std::runtime_error(join(file, location, message)),
      file_(std::move(file)),
      location_(std::move(location)),
      message_(std::move(message)) {}

InputError InputError::in_file(std::string file) const { return {std::move(file), location_, message_}; }

}  // namespace reconfig
