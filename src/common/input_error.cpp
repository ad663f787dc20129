#include "reconfig/common/input_error.h"

#include <fmt/format.h>

#include <utility>

namespace reconfig {
namespace {

/// `text` with control characters written as `\xNN` (a file must not be able to send escape
/// sequences to the terminal) and cut to `kMaxInputErrorPart` characters.
std::string printable(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  for (; i < text.size() && out.size() < kMaxInputErrorPart; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f)
      out += fmt::format("\\x{:02x}", c);
    else
      out += text[i];
  }
  if (i == text.size()) return out;
  // Cut on a character boundary (never inside a UTF-8 sequence) and say how much is left out.
  while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0x80) out.pop_back();
  if (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0xC0) out.pop_back();
  return fmt::format("{}… ({} characters in all)", out, text.size());
}

std::string join(const std::string& file, const std::string& location, const std::string& message) {
  std::string line;
  if (!file.empty()) line += file + ": ";
  if (!location.empty()) line += location + ": ";
  return line + message;
}

}  // namespace

InputError::InputError(std::string file, std::string location, std::string message)
    : std::runtime_error(join(printable(file), printable(location), printable(message))),
      file_(std::move(file)),
      location_(std::move(location)),
      message_(std::move(message)) {}

InputError InputError::in_file(std::string file) const { return {std::move(file), location_, message_}; }

}  // namespace reconfig
