#include "keys.h"

#include <cctype>
#include <string>

namespace reconfig::studio::keys {

int from_name(const char* name) {
  std::string key(name);
  for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (key.size() == 1 && std::isalpha(static_cast<unsigned char>(key[0]))) return std::toupper(key[0]);
  static const std::pair<const char*, int> kNamed[] = {
      {"space", kSpace},   {"escape", kEscape}, {"enter", kEnter},       {"tab", kTab},     {"backspace", kBackspace},
      {"insert", kInsert}, {"delete", kDelete}, {"right", kRight},       {"left", kLeft},   {"down", kDown},
      {"up", kUp},         {"pageup", kPageUp}, {"pagedown", kPageDown}, {"home", kHome},   {"end", kEnd}};
  for (const auto& [named, code] : kNamed)
    if (key == named) return code;
  return -1;
}

}  // namespace reconfig::studio::keys
