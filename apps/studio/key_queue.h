#pragma once
/// @file
/// Key presses and releases in the order they happened, handed to ImGui at most one change per
/// key per frame. ImGui 1.86 reads key state once a frame, so a tap shorter than a frame (a
/// press and its release between two frames, common under software rendering) was lost: 5
/// quick taps of Right gave 3 steps. Replayed from the queue, a tap is down for one frame and
/// up the next.

#include <deque>
#include <vector>

namespace reconfig::studio {

/// One key event (GLFW's key code, and the scancode and modifiers the GLFW backend wants).
struct KeyEvent {
  int key = 0;
  bool down = false;
  int scancode = 0;
  int mods = 0;
};

class KeyQueue {
 public:
  void push(const KeyEvent& event) { events_.push_back(event); }
  bool empty() const { return events_.empty(); }
  /// The events for this frame: the queued ones in order, up to (not including) the first of
  /// a key that already changed in this frame. Order across keys is kept, so a modifier held
  /// around several taps stays down for all of them.
  std::vector<KeyEvent> take_frame();

 private:
  std::deque<KeyEvent> events_;
};

}  // namespace reconfig::studio
