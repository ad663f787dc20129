#include "reconfig/render/image.h"

#include <stb_image_write.h>  // implementation in Debian's libstb (pkg-config stb)

#include <cassert>

#include "reconfig/common/input_error.h"

namespace reconfig::render {

void write_png(const std::filesystem::path& path, const Image& image) {
  assert(image.rgba.size() == static_cast<std::size_t>(image.width) * image.height * 4);
  if (image.width <= 0 || image.height <= 0) throw InputError(path.string(), "", "cannot write an empty image");
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw InputError(path.string(), "", "cannot write the PNG file (does the folder exist and is it writable?)");
}

}  // namespace reconfig::render
