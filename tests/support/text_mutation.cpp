#include "support/text_mutation.h"

#include <algorithm>
#include <cstdlib>

namespace reconfig::testing {

std::string mutate_text(const std::string& original, std::mt19937& rng, const std::vector<std::string>& tokens,
                        std::size_t max_range) {
  std::string s = original;
  const auto pick = [&](std::size_t n) { return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n); };
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    switch (rng() % 7) {
      case 0:  // random byte
        if (!s.empty()) s[pick(s.size())] = static_cast<char>(rng() & 0xff);
        break;
      case 1:  // flip one bit
        if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1 << (rng() % 8));
        break;
      case 2:  // truncate
        s.resize(pick(s.size() + 1));
        break;
      case 3: {  // delete a range
        const std::size_t at = pick(s.size() + 1), length = pick(std::min(max_range, s.size() - at + 1));
        s.erase(at, length);
        break;
      }
      case 4: {  // duplicate a range
        const std::size_t at = pick(s.size() + 1), length = pick(std::min(max_range, s.size() - at + 1));
        s.insert(pick(s.size() + 1), s.substr(at, length));
        break;
      }
      default: {  // insert or overwrite with a token
        if (tokens.empty()) break;
        const std::string& token = tokens[pick(tokens.size())];
        const std::size_t at = pick(s.size() + 1);
        if (rng() % 2) s.insert(at, token);
        else s.replace(at, std::min(token.size(), s.size() - at), token);
        break;
      }
    }
  }
  return s;
}

int fuzz_setting(const char* name, int fallback) {
  const char* value = std::getenv(name);
  return value ? std::atoi(value) : fallback;
}

}  // namespace reconfig::testing
