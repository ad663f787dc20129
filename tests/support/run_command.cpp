#include "support/run_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/test_data.h"

namespace reconfig::testing {
namespace {

std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

CommandResult run_tool(const std::string& tool, const std::string& arguments) {
  static int runs = 0;  // a folder of its own: the calling test may be using fresh_temp_dir()
  const std::filesystem::path dir =
      binary_dir() / "test-tmp" / ("run." + std::to_string(::getpid()) + "." + std::to_string(++runs));
  std::filesystem::create_directories(dir);
  const std::string command = (binary_dir() / "bin" / tool).string() + " " + arguments + " >" +
                              (dir / "out").string() + " 2>" + (dir / "err").string() + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(dir / "out");
  result.err = slurp(dir / "err");
  return result;
}

CommandResult run_reconfig(const std::string& arguments) { return run_tool("reconfig", arguments); }

}  // namespace reconfig::testing
