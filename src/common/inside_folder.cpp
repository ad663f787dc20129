#include "reconfig/common/inside_folder.h"

#include <fmt/format.h>

#include "reconfig/common/input_error.h"

namespace reconfig {
namespace fs = std::filesystem;

namespace {

fs::path resolved(const fs::path& path, const std::string& reference) {
  std::error_code error;
  fs::path out = fs::weakly_canonical(path, error);
  if (error) throw InputError("", "", fmt::format("cannot resolve \"{}\": {}", reference, error.message()));
  return out;
}

/// Whether `path` is `folder` or lies under it (both without `.` or `..`).
bool is_under(const fs::path& path, const fs::path& folder) {
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

/// Whether `path` stays under `folder` through its symbolic links, read as the kernel reads it
/// and as its lexically normal form (what a loader may open instead): `missing/../link` is
/// `link` once normalized.
bool resolves_under(const fs::path& path, const fs::path& folder, const std::string& reference) {
  const fs::path real_folder = resolved(folder, reference);
  return is_under(resolved(path, reference), real_folder) &&
         is_under(resolved(path.lexically_normal(), reference), real_folder);
}

}  // namespace

std::string outside_folder_problem(const fs::path& folder, const std::string& reference) {
  const fs::path written(reference);
  fs::path base = fs::absolute(folder).lexically_normal();
  if (!base.has_filename()) base = base.parent_path();  // "dir/" → "dir"
  std::string how;
  if (written.is_absolute())
    how = "is an absolute path";
  else if (!is_under((base / written).lexically_normal(), base))
    how = "leads out of the file's folder with \"..\"";
  else if (!resolves_under(base / written, base, reference))
    how = "leads out of the file's folder through a symbolic link";
  else
    return "";
  return fmt::format("\"{}\" {}: a design reads only files in its own folder and below, unless outside paths are "
                     "allowed (--allow-outside-paths)",
                     reference, how);
}

}  // namespace reconfig
