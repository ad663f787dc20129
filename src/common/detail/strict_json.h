#pragma once
// JSON as the loaders read it: nesting bounded, duplicate keys and control characters in keys
// refused (docs/file-formats.md, "Limits"), and user values described, never dumped whole.

#include <nlohmann/json.hpp>
#include <string>

namespace reconfig::detail {

/// The deepest nesting of arrays and objects a loader accepts (a scene file needs 8 levels).
inline constexpr int kMaxJsonDepth = 100;

/// Parses `text`, refusing what nlohmann would accept silently or die on: nesting deeper than
/// `kMaxJsonDepth` (printing or destroying such a value recurses as deep), a key given twice
/// in one object ("last one wins" hides a mistake), a key with a control character.
/// @throws InputError (empty file name) with the JSON path of the problem; malformed JSON gets
///   nlohmann's message ("malformed JSON: parse error at line 3, column 5: ...") and no path
nlohmann::json parse_strict_json(const std::string& text);

/// A user value as an error message shows it: its type and a bounded prefix
/// (`the number 4294967297`, `the string "abc…"`, `an array of 3 elements`).
std::string describe_json(const nlohmann::json& value);

}  // namespace reconfig::detail
