// Every command the README, docs/*.md and examples/*/README.md show in a ```sh block and that starts with
// `build/bin/reconfig` (the CLI and the studio) runs as written and succeeds: exit code 0, or
// 0 or 1 for `check` (1: collisions found). Each runs in a fresh folder of its own that looks
// like the repository (`examples`, `build` linked in, an empty `out/` as the tour's
// `mkdir -p out` makes), so what it writes stays out of the source tree; the README's
// commands write nothing outside `out/`. A command whose comment says it needs a display (a
// window) is the one kind left out.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

namespace fs = std::filesystem;

struct DocCommand {
  std::string file;  ///< relative to the repository, e.g. "docs/benchmarks.md"
  int line = 0;
  std::string command;
};

void PrintTo(const DocCommand& c, std::ostream* out) { *out << c.file << ":" << c.line << ": " << c.command; }

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

std::vector<DocCommand> commands_in(const std::string& relative) {
  std::vector<DocCommand> commands;
  std::ifstream in(testing::source_dir() / relative);
  bool in_block = false, in_sh = false;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (starts_with(line, "```")) {
      in_sh = !in_block && line == "```sh";
      in_block = !in_block;
    } else if (in_sh && starts_with(line, "build/bin/reconfig") && line.find("needs a display") == std::string::npos) {
      commands.push_back({relative, number, line});
    }
  }
  return commands;
}

std::vector<DocCommand> documented_commands() {
  std::vector<std::string> files = {"README.md"};
  for (const auto& entry : fs::directory_iterator(testing::source_dir() / "docs"))
    if (entry.path().extension() == ".md") files.push_back("docs/" + entry.path().filename().string());
  for (const auto& entry : fs::directory_iterator(testing::source_dir() / "examples"))
    if (fs::exists(entry.path() / "README.md"))
      files.push_back("examples/" + entry.path().filename().string() + "/README.md");
  std::sort(files.begin() + 1, files.end());
  std::vector<DocCommand> commands;
  for (const std::string& file : files)
    for (DocCommand& c : commands_in(file)) commands.push_back(std::move(c));
  return commands;
}

/// `README_line57_info`, `benchmarks_line75_bench`, `ccd_queries_README_line14_ccd_queries`.
std::string test_name(const DocCommand& c) {
  const fs::path file(c.file);
  const std::string stem =
      starts_with(c.file, "examples/") ? file.parent_path().filename().string() + "_README" : file.stem().string();
  const std::string tool = c.command.substr(std::string("build/bin/").size());
  std::string word = starts_with(tool, "reconfig-studio") ? "studio" : tool.substr(9, tool.find(' ', 9) - 9);
  std::string name = stem + "_line" + std::to_string(c.line) + "_" + word;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

/// A folder like the repository root for one command, with an empty `out/`.
fs::path working_folder() {
  const fs::path dir = testing::fresh_temp_dir();
  fs::create_directory_symlink(testing::source_dir() / "examples", dir / "examples");
  fs::create_directory_symlink(testing::binary_dir(), dir / "build");
  fs::create_directory(dir / "out");
  return dir;
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

class DocsCommands : public ::testing::TestWithParam<DocCommand> {};

TEST_P(DocsCommands, RunAsWritten) {
  const DocCommand& c = GetParam();
  if (starts_with(c.command, "build/bin/reconfig bench ") && !fs::exists(testing::binary_dir() / "bin" / "bench_linkage"))
    GTEST_SKIP() << "configured with RECONFIG_BUILD_BENCH=OFF";
  const fs::path dir = working_folder();
  const std::set<std::string> before = entries(dir);
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  // The command on a line of its own: its `# comment` ends there.
  const std::string shell = "cd '" + dir.string() + "' && {\n" + c.command + "\n} >'" + out.string() + "' 2>'" +
                            err.string() + "' </dev/null";
  const int status = std::system(shell.c_str());
  const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err_in(err);
  const std::string errors((std::istreambuf_iterator<char>(err_in)), std::istreambuf_iterator<char>());
  const bool check = starts_with(c.command, "build/bin/reconfig check ");
  EXPECT_TRUE(exit_code == 0 || (check && exit_code == 1))
      << c.file << ":" << c.line << ": `" << c.command << "` exited " << exit_code << "\n" << errors;
  if (c.file == "README.md") {
    std::set<std::string> after = entries(dir);
    for (const char* ours : {"stdout.txt", "stderr.txt"}) after.erase(ours);
    EXPECT_EQ(after, before) << "README.md:" << c.line << " writes outside out/";
  }
}

INSTANTIATE_TEST_SUITE_P(Docs, DocsCommands, ::testing::ValuesIn(documented_commands()),
                         [](const ::testing::TestParamInfo<DocCommand>& param) { return test_name(param.param); });

TEST(DocsCommandsFound, TheTourAndTheBenchmarkRecipe) {
  const std::vector<DocCommand> commands = documented_commands();
  const auto count = [&](const std::string& file) {
    return std::count_if(commands.begin(), commands.end(), [&](const DocCommand& c) { return c.file == file; });
  };
  EXPECT_GE(count("README.md"), 10);
  EXPECT_GE(count("docs/benchmarks.md"), 2);
}

}  // namespace
}  // namespace reconfig
