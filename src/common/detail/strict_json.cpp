#include "common/detail/strict_json.h"

#include <fmt/format.h>

#include <set>
#include <vector>

#include "reconfig/common/input_error.h"

namespace reconfig::detail {
namespace {

using nlohmann::json;

constexpr std::size_t kShownCharacters = 40;

/// The containers open at the parser's position, each with the child being read.
class OpenContainers {
 public:
  bool on_event(json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
          throw InputError("", path(), fmt::format("nested deeper than {} levels", kMaxJsonDepth));
        frames_.push_back({event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        next_element();
        break;
      case json::parse_event_t::key: add_key(parsed.get<std::string>()); break;
      case json::parse_event_t::value: next_element(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;  // arrays: the element being read
    std::set<std::string> keys;
    std::string key;  // objects: the member being read
  };

  void add_key(const std::string& key) {
    Frame& frame = frames_.back();
    frame.key = key;
    for (const char c : key)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        throw InputError("", path(), "a key must not contain control characters");
    if (!frame.keys.insert(key).second) throw InputError("", path(), "duplicate key (given twice in one object)");
  }

  void next_element() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  std::string path() const {
    std::string out;
    for (const Frame& frame : frames_) {
      if (frame.array)
        out += fmt::format("[{}]", frame.index);
      else if (!frame.key.empty() || !frame.keys.empty())
        out += (out.empty() ? "" : ".") + frame.key;
    }
    return out;
  }

  std::vector<Frame> frames_;
};

std::string bounded(const std::string& text) {
  if (text.size() <= kShownCharacters) return text;
  std::size_t cut = kShownCharacters;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "…";
}

}  // namespace

json parse_strict_json(const std::string& text) {
  OpenContainers open;
  try {
    return json::parse(text, [&](int, json::parse_event_t event, json& parsed) { return open.on_event(event, parsed); });
  } catch (const json::exception& error) {  // parse_error, and out_of_range for a number like 1e999
    // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    std::string message = error.what();
    const auto at = message.find("] ");
    if (at != std::string::npos) message = message.substr(at + 2);
    throw InputError("", "", "malformed JSON: " + message);
  }
}

std::string describe_json(const json& value) {
  switch (value.type()) {
    case json::value_t::object: return fmt::format("an object of {} member{}", value.size(), value.size() == 1 ? "" : "s");
    case json::value_t::array: return fmt::format("an array of {} element{}", value.size(), value.size() == 1 ? "" : "s");
    case json::value_t::string: return fmt::format("the string \"{}\"", bounded(value.get<std::string>()));
    case json::value_t::null: return "null";
    case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    default: return "the number " + bounded(value.dump());
  }
}

}  // namespace reconfig::detail
