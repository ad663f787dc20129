#pragma once
/// @file
/// GLB files built in tests: the binary container of glTF 2.0 around a JSON and a BIN chunk.

#include <cstdint>
#include <string>

namespace reconfig::testing {

inline void append_u32(std::string& out, std::uint32_t value) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>(value >> (8 * k) & 0xff));
}

/// A GLB with `json` and `binary` as its chunks (each padded to 4 bytes).
inline std::string glb(std::string json, std::string binary) {
  while (json.size() % 4) json += ' ';
  while (binary.size() % 4) binary += '\0';
  std::string out = "glTF";
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + binary.size()));
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  out += "JSON" + json;
  append_u32(out, static_cast<std::uint32_t>(binary.size()));
  return out + std::string("BIN\0", 4) + binary;
}

}  // namespace reconfig::testing
