#include "reconfig/common/write_atomically.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include "reconfig/common/input_error.h"

namespace reconfig {

void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  fs::path temp = path;
  temp += ".tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string(), "", std::string("cannot open for writing: ") + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temp, ignored);
      throw InputError(path.string(), "", "write failed");
    }
  }
  std::error_code error;
  fs::rename(temp, path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw InputError(path.string(), "", "cannot replace the file: " + error.message());
  }
}

}  // namespace reconfig
