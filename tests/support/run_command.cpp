#include "support/run_command.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
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

std::filesystem::path fresh_run_dir() {
  static int runs = 0;  // a folder of its own: the calling test may be using fresh_temp_dir()
  const std::filesystem::path dir =
      binary_dir() / "test-tmp" / ("run." + std::to_string(::getpid()) + "." + std::to_string(++runs));
  std::filesystem::create_directories(dir);
  return dir;
}

std::string redirections(const std::filesystem::path& dir) {
  return " >" + (dir / "out").string() + " 2>" + (dir / "err").string() + " </dev/null";
}

/// Whether process `pid` has a handler for SIGINT: bit 2 of the SigCgt mask in /proc.
bool catches_sigint(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1)) & 1;
  return false;
}

/// Waits up to 30 s for `pid` to catch SIGINT; false if it exited or never did.
bool wait_until_catching_sigint(pid_t pid) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < give_up) {
    if (catches_sigint(pid)) return true;
    siginfo_t exited{};
    if (::waitid(P_PID, pid, &exited, WEXITED | WNOHANG | WNOWAIT) == 0 && exited.si_pid == pid) return false;
    ::usleep(2000);
  }
  return false;
}

}  // namespace

CommandResult run_tool(const std::string& tool, const std::string& arguments) {
  const std::filesystem::path dir = fresh_run_dir();
  const std::string command = (binary_dir() / "bin" / tool).string() + " " + arguments + redirections(dir);
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(dir / "out");
  result.err = slurp(dir / "err");
  return result;
}

CommandResult run_reconfig(const std::string& arguments) { return run_tool("reconfig", arguments); }

CommandResult run_reconfig_interrupted(const std::vector<std::string>& arguments) {
  const std::filesystem::path dir = fresh_run_dir();
  const std::string tool = (binary_dir() / "bin" / "reconfig").string();
  std::vector<char*> argv{const_cast<char*>(tool.c_str())};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const std::string out = (dir / "out").string(), err = (dir / "err").string();
  const pid_t pid = ::fork();
  if (pid == 0) {  // no shell in between: a shell catches SIGINT itself
    ::dup2(::open("/dev/null", O_RDONLY), 0);
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    ::execv(tool.c_str(), argv.data());
    ::_exit(127);
  }
  const bool caught = wait_until_catching_sigint(pid);
  if (caught) ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(dir / "out");
  result.err = (caught ? "" : "[it never caught SIGINT] ") + slurp(dir / "err");
  return result;
}

}  // namespace reconfig::testing
