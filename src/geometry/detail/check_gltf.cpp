#include "geometry/detail/check_gltf.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "common/detail/strict_json.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/inside_folder.h"
#include "reconfig/common/read_input_file.h"

namespace reconfig::geometry::detail {
namespace {

using nlohmann::json;
using Entries = std::vector<std::pair<std::string, const json*>>;  // id ("3", or glTF 1's name), value

constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"

[[noreturn]] void fail(const std::string& location, const std::string& message) {
  throw InputError("", location, message);
}

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = value << 8 | static_cast<unsigned char>(bytes[at + k]);
  return value;
}

/// A GLB's JSON text and the size of its binary chunk (0 if none), after checking that every
/// length it declares fits in the file.
std::pair<std::string, std::uint64_t> split_glb(const std::string& bytes) {
  if (bytes.size() < 20) fail("GLB header", fmt::format("a GLB file has at least 20 bytes, this one {}", bytes.size()));
  const std::uint32_t version = u32_at(bytes, 4);
  const std::uint32_t length = u32_at(bytes, 8);
  if (length > bytes.size())
    fail("GLB header", fmt::format("declares {} bytes, the file has {}", length, bytes.size()));
  if (version == 1) {  // 20-byte header: magic, version, length, JSON length, JSON format
    const std::uint64_t content = u32_at(bytes, 12);
    if (20 + content > length) fail("GLB header", fmt::format("declares {} bytes of JSON, the file has {} after the header", content, length - 20));
    return {bytes.substr(20, content), length - 20 - content};
  }
  if (version != 2) fail("GLB header", fmt::format("unknown GLB version {}", version));
  std::string text;
  std::uint64_t binary = 0;
  int index = 0;
  for (std::uint64_t at = 12; at < length; ++index) {
    const std::string where = fmt::format("GLB chunk {}", index);
    if (at + 8 > length) fail(where, "truncated chunk header");
    const std::uint64_t size = u32_at(bytes, at);
    if (at + 8 + size > length)
      fail(where, fmt::format("declares {} bytes, the file has {} after the chunk header", size, length - at - 8));
    if (index == 0 && u32_at(bytes, at + 4) != kJsonChunk) fail(where, "the first chunk must be JSON");
    if (index == 0) text = bytes.substr(at + 8, size);
    if (index == 1) binary = size;
    at += 8 + size;
  }
  if (index == 0) fail("GLB header", "no JSON chunk");
  return {text, binary};
}

/// The members of `document[key]`, an array (glTF 2) or an object of named entries (glTF 1).
Entries entries(const json& document, const char* key) {
  Entries out;
  const auto it = document.find(key);
  if (it == document.end()) return out;
  if (it->is_array())
    for (std::size_t i = 0; i < it->size(); ++i) out.emplace_back(std::to_string(i), &(*it)[i]);
  else if (it->is_object())
    for (const auto& item : it->items()) out.emplace_back(item.key(), &item.value());
  else
    fail(key, "expected an array");
  return out;
}

std::string location(const char* list, const std::string& id, const char* field = nullptr) {
  std::string out = std::isdigit(static_cast<unsigned char>(id[0])) ? fmt::format("{}[{}]", list, id)
                                                                     : fmt::format("{}.{}", list, id);
  return field ? out + "." + field : out;
}

/// `object[key]` as a byte count or index; `fallback` if absent.
std::uint64_t count_field(const json& object, const char* key, const std::string& where, std::uint64_t fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned()) fail(where + "." + key, "expected a non-negative integer");
  return it->get<std::uint64_t>();
}

/// A reference to another entry: an index (glTF 2) or a name (glTF 1).
std::optional<std::string> reference(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) return std::nullopt;
  if (it->is_number_unsigned()) return std::to_string(it->get<std::uint64_t>());
  if (it->is_string() && !it->get<std::string>().empty()) return it->get<std::string>();
  fail(where + "." + key, "expected an index");
}

std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

/// The bytes a URI gives, after checking that a file it names stays inside `folder`.
std::uint64_t uri_bytes(const json& entry, const std::string& where, const std::filesystem::path& folder,
                        bool allow_outside_paths) {
  const auto it = entry.find("uri");
  if (!it->is_string()) fail(where + ".uri", "expected a string");
  const std::string uri = it->get<std::string>();
  if (uri.rfind("data:", 0) == 0) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos) fail(where + ".uri", "a data URI needs a comma");
    const std::uint64_t payload = uri.size() - comma - 1;
    return uri.find(";base64") < comma ? payload / 4 * 3 : payload;
  }
  for (const std::string& written : {uri, percent_decoded(uri)}) {
    if (allow_outside_paths) break;
    try {
      if (const std::string problem = outside_folder_problem(folder, written); !problem.empty())
        fail(where + ".uri", problem);
    } catch (const InputError& error) {
      if (!error.location().empty()) throw;
      fail(where + ".uri", error.message());
    }
  }
  try {
    return check_input_file(folder / percent_decoded(uri));
  } catch (const InputError& error) {
    fail(where + ".uri", fmt::format("\"{}\" {}", error.file(), error.message()));
  }
}

/// The byte length of each buffer, checked against the data that is there.
std::map<std::string, std::uint64_t> check_buffers(const json& document, std::uint64_t glb_binary,
                                                   const std::filesystem::path& folder, bool allow_outside_paths) {
  std::map<std::string, std::uint64_t> lengths;
  for (const auto& [id, buffer] : entries(document, "buffers")) {
    const std::string where = location("buffers", id);
    if (!buffer->is_object()) fail(where, "expected an object");
    const std::uint64_t declared = count_field(*buffer, "byteLength", where, 0);
    const bool external = buffer->contains("uri") && id != "binary_glTF";  // glTF 1's GLB body
    const std::uint64_t there = external ? uri_bytes(*buffer, where, folder, allow_outside_paths) : glb_binary;
    if (declared > there)
      fail(where + ".byteLength", fmt::format("declares {} bytes, its data has {}", declared, there));
    lengths[id] = declared;
  }
  for (const auto& [id, image] : entries(document, "images"))
    if (image->is_object() && image->contains("uri")) uri_bytes(*image, location("images", id), folder, allow_outside_paths);
  return lengths;
}

struct View {
  std::uint64_t length;
  std::uint64_t stride;
};

std::map<std::string, View> check_buffer_views(const json& document, const std::map<std::string, std::uint64_t>& buffers) {
  std::map<std::string, View> views;
  for (const auto& [id, view] : entries(document, "bufferViews")) {
    const std::string where = location("bufferViews", id);
    if (!view->is_object()) fail(where, "expected an object");
    const auto buffer = reference(*view, "buffer", where);
    const auto it = buffer ? buffers.find(*buffer) : buffers.end();
    if (it == buffers.end()) fail(where + ".buffer", "refers to no buffer");
    const std::uint64_t offset = count_field(*view, "byteOffset", where, 0);
    const std::uint64_t length = count_field(*view, "byteLength", where, 0);
    if (offset > it->second || length > it->second - offset)
      fail(where, fmt::format("bytes {} to {} lie beyond its buffer's {} bytes", offset, offset + length, it->second));
    views[id] = {length, count_field(*view, "byteStride", where, 0)};
  }
  return views;
}

std::uint64_t element_bytes(const json& accessor, const std::string& where) {
  static const std::map<std::uint64_t, std::uint64_t> component = {{5120, 1}, {5121, 1}, {5122, 2},
                                                                     {5123, 2}, {5125, 4}, {5126, 4}};
  static const std::map<std::string, std::uint64_t> components = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                                   {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
  const auto c = component.find(count_field(accessor, "componentType", where, 0));
  const auto type = accessor.find("type");
  const auto n = type != accessor.end() && type->is_string() ? components.find(type->get<std::string>()) : components.end();
  if (c == component.end()) fail(where + ".componentType", "unknown component type");
  if (n == components.end()) fail(where + ".type", "unknown accessor type");
  return c->second * n->second;
}

void check_accessors(const json& document, const std::map<std::string, View>& views) {
  for (const auto& [id, accessor] : entries(document, "accessors")) {
    const std::string where = location("accessors", id);
    if (!accessor->is_object()) fail(where, "expected an object");
    const std::uint64_t count = count_field(*accessor, "count", where, 0);
    const std::uint64_t element = element_bytes(*accessor, where);
    if (count > kMaxInputFileBytes / element)
      fail(where + ".count", fmt::format("{} elements of {} bytes are more than a loader reads", count, element));
    const auto view_id = reference(*accessor, "bufferView", where);
    if (!view_id || count == 0) continue;  // no view: zeros (bounded above)
    const auto view = views.find(*view_id);
    if (view == views.end()) fail(where + ".bufferView", "refers to no buffer view");
    const std::uint64_t stride = std::max({view->second.stride, count_field(*accessor, "byteStride", where, 0), element});
    const std::uint64_t end = count_field(*accessor, "byteOffset", where, 0) + stride * (count - 1) + element;
    if (end > view->second.length)
      fail(where, fmt::format("needs {} bytes of its buffer view, which has {}", end, view->second.length));
  }
}

/// Each node's children, as indices into `nodes`; refuses children that do not exist.
std::vector<std::vector<std::size_t>> children_of(const Entries& nodes) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < nodes.size(); ++i) index[nodes[i].first] = i;
  std::vector<std::vector<std::size_t>> children(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string where = location("nodes", nodes[i].first);
    if (!nodes[i].second->is_object()) fail(where, "expected an object");
    const auto list = nodes[i].second->find("children");
    if (list == nodes[i].second->end()) continue;
    if (!list->is_array()) fail(where + ".children", "expected an array");
    for (std::size_t k = 0; k < list->size(); ++k) {
      const json& child = (*list)[k];
      const std::string id = child.is_number_unsigned() ? std::to_string(child.get<std::uint64_t>())
                                                        : child.is_string() ? child.get<std::string>() : "";
      const auto it = index.find(id);
      if (it == index.end()) fail(fmt::format("{}.children[{}]", where, k), "refers to no node");
      children[i].push_back(it->second);
    }
  }
  return children;
}

/// Refuses a node tree deeper than kMaxGltfNodeDepth or with a cycle: depth first from each
/// node not yet done, without recursion, each node's height (its levels, itself included)
/// computed once.
void check_node_tree(const json& document) {
  const Entries nodes = entries(document, "nodes");
  const std::vector<std::vector<std::size_t>> children = children_of(nodes);
  std::vector<int> height(nodes.size(), 0);  // 0: not visited, -1: on the current path
  for (std::size_t root = 0; root < nodes.size(); ++root) {
    if (height[root] != 0) continue;
    std::vector<std::pair<std::size_t, std::size_t>> path{{root, 0}};  // node, next child
    height[root] = -1;
    while (!path.empty()) {
      auto& [node, next] = path.back();
      if (next < children[node].size()) {
        const std::size_t child = children[node][next++];
        if (height[child] == -1) fail(location("nodes", nodes[child].first), "the node is its own ancestor (a cycle)");
        if (height[child] == 0) {
          height[child] = -1;
          path.emplace_back(child, 0);
        }
        continue;
      }
      int levels = 1;
      for (const std::size_t child : children[node]) levels = std::max(levels, height[child] + 1);
      if (levels > kMaxGltfNodeDepth)
        fail(location("nodes", nodes[node].first),
             fmt::format("the node tree under it is deeper than {} levels", kMaxGltfNodeDepth));
      height[node] = levels;
      path.pop_back();
    }
  }
}

}  // namespace

bool looks_like_gltf(const std::string& extension, const std::string& bytes) {
  if (extension == "gltf" || extension == "glb" || bytes.rfind("glTF", 0) == 0) return true;
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string::npos && bytes[first] == '{';
}

void check_gltf(const std::string& bytes, const std::filesystem::path& folder, bool allow_outside_paths) {
  const bool binary = bytes.rfind("glTF", 0) == 0;
  const auto [text, glb_binary] = binary ? split_glb(bytes) : std::pair{bytes, std::uint64_t{0}};
  const json document = reconfig::detail::parse_strict_json(text);
  if (!document.is_object()) fail("", "expected a glTF JSON object");
  const auto buffers = check_buffers(document, glb_binary, folder, allow_outside_paths);
  check_accessors(document, check_buffer_views(document, buffers));
  check_node_tree(document);
}

}  // namespace reconfig::geometry::detail
