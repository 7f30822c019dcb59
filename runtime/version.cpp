// SPDX-License-Identifier: MIT
#include "version.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace flange::runtime {

std::string version() { return FLANGE_VERSION; }

std::string generated_by(const std::string& command) {
  return command + " (flange " + version() + ")";
}

std::string generated_by(const std::vector<std::string>& args) {
  std::string command = "flange";
  for (const std::string& arg : args) command += " " + arg;
  return generated_by(command);
}

std::string tool_version(const std::vector<std::string>& argv) {
  const std::string not_found = "not found";
  if (argv.empty()) return not_found;
  int out[2];
  if (::pipe(out) != 0) return not_found;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  std::string text;
  if (started == 0) {
    char buffer[4096];
    ssize_t n = 0;
    while ((n = ::read(out[0], buffer, sizeof buffer)) > 0) text.append(buffer, n);
  }
  ::close(out[0]);
  if (started != 0) return not_found;
  int status = 0;
  if (::waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return not_found;
  }
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? not_found : line;
}

}  // namespace flange::runtime
