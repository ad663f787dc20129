#pragma once
/// @file
/// The status bar at the bottom: the studio's status message (cut to the room left of the
/// collision line, red for an error) and the collision summary; a message too long for it opens
/// in a window of its own with a "more" button (an error opens it by itself). Owns whether that
/// window is open; the message is the studio's (Studio::status).

namespace reconfig::studio {

class Studio;

class StatusBar {
 public:
  void draw(Studio& studio);
  /// A new message is shown: the window closes; an error opens it once it turns out cut.
  void message_changed(bool error);
  /// Whether the window with the whole message is open.
  bool window_open() const { return window_open_; }

 private:
  void draw_window(const Studio& studio);

  bool window_open_ = false;  ///< the whole message in a window
  bool window_due_ = false;   ///< an error not yet shown: open the window if it is cut
};

}  // namespace reconfig::studio
