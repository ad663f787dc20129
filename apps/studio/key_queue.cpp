#include "key_queue.h"

#include <set>

namespace reconfig::studio {

std::vector<KeyEvent> KeyQueue::take_frame() {
  std::vector<KeyEvent> frame;
  std::set<int> changed;
  while (!events_.empty() && changed.insert(events_.front().key).second) {
    frame.push_back(events_.front());
    events_.pop_front();
  }
  return frame;
}

}  // namespace reconfig::studio
