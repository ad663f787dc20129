#pragma once
/// @file
/// The error every loader and validator throws for bad user data.

#include <stdexcept>
#include <string>

namespace reconfig {

/// `what()` shows at most this many characters of each of the file, location and message
/// (user data such as a 200 MB JSON value never becomes a 200 MB message).
inline constexpr std::size_t kMaxInputErrorPart = 1000;

/// A recoverable failure caused by user data (a file, a JSON value, a mesh element).
///
/// It names where the problem is so the user can fix it: the file, a location inside it
/// (a JSON path such as `transitions[0].tracks.seat.rotation[1].time`, a line number, a face
/// index), and what is wrong. `what()` joins them into one line:
/// `scene.json: transitions[0].tracks.seat.rotation[1].time: keyframe times must increase`.
/// In `what()` control characters are written as `\xNN` (no escape sequences reach the
/// terminal) and each part is cut to `kMaxInputErrorPart` characters; the accessors return the
/// parts as given.
class InputError : public std::runtime_error {
 public:
  /// @param file      the file the data came from (may be empty for in-memory data)
  /// @param location  where inside it (may be empty)
  /// @param message   what is wrong, lower case, no trailing period
  InputError(std::string file, std::string location, std::string message);

  const std::string& file() const { return file_; }
  const std::string& location() const { return location_; }
  const std::string& message() const { return message_; }

  /// The same error attributed to `file` (used when an in-memory parser's error is rethrown
  /// by the loader that knows the file name). Keeps the location and message.
  InputError in_file(std::string file) const;

 private:
  std::string file_;
  std::string location_;
  std::string message_;
};

}  // namespace reconfig
