#include "common/detail/strict_json.h"

#include <fmt/format.h>

#include <set>
#include <vector>

#include "reconfig/common/input_error.h"

namespace reconfig::detail {
namespace {

using nlohmann::json;

constexpr std::size_t kShownCharacters = 40;

/// A first, checking pass over the text (nlohmann's SAX interface): the containers open at
/// the parser's position, each with the child being read. (The DOM parser's callback would do
/// too, but it scans the parent container at every object's end: quadratic in 10,000 parts.)
class StrictChecker : public nlohmann::json_sax<json> {
 public:
  bool null() override { return next_element(); }
  bool boolean(bool) override { return next_element(); }
  bool number_integer(number_integer_t) override { return next_element(); }
  bool number_unsigned(number_unsigned_t) override { return next_element(); }
  bool number_float(number_float_t, const string_t&) override { return next_element(); }
  bool string(string_t&) override { return next_element(); }
  bool binary(binary_t&) override { return next_element(); }
  bool start_object(std::size_t) override { return open(false); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& key) override {
    Frame& frame = frames_.back();
    frame.key = key;
    for (const char c : key)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        throw InputError("", path(), "a key must not contain control characters");
    if (!frame.keys.insert(key).second) throw InputError("", path(), "duplicate key (given twice in one object)");
    return true;
  }

  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
    // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    std::string message = error.what();
    const auto at = message.find("] ");
    if (at != std::string::npos) message = message.substr(at + 2);
    throw InputError("", "", "malformed JSON: " + message);
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;  // arrays: the element being read
    std::set<std::string> keys;
    std::string key;  // objects: the member being read
  };

  bool open(bool array) {
    if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
      throw InputError("", path(), fmt::format("nested deeper than {} levels", kMaxJsonDepth));
    frames_.push_back({array, 0, {}, {}});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return next_element();
  }

  bool next_element() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }

  std::string path() const {
    std::string out;
    for (const Frame& frame : frames_) {
      if (frame.array)
        out += fmt::format("[{}]", frame.index);
      else if (!frame.keys.empty())
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
  StrictChecker checker;
  json::sax_parse(text, &checker);
  return json::parse(text);  // as checked: well formed, shallow enough to build and print
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
