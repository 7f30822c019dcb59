// SPDX-License-Identifier: MIT
#include "verilated_runner.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "data_dir.h"

extern char** environ;

namespace flange::tb {

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read", path.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// FNV-1a, 64 bits: enough to tell builds apart, not a security measure.
std::uint64_t fnv1a(std::uint64_t h, const std::string& bytes) {
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

// Runs argv[0] (searched in PATH) with stdout and stderr sent to files; returns the exit status
// (127 when it could not be started).
int spawn(const std::vector<std::string>& argv, const fs::path& out_file, const fs::path& err_file,
          const std::vector<std::string>& extra_env = {}) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e) env_strings.emplace_back(*e);
  for (const std::string& e : extra_env) env_strings.push_back(e);
  std::vector<char*> env;
  for (std::string& e : env_strings) env.push_back(e.data());
  env.push_back(nullptr);

  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return 127;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 127;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// An exclusive flock(2) held for the object's lifetime; the kernel drops it if the process dies.
class BuildLock {
 public:
  explicit BuildLock(const fs::path& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT, 0644)) {
    if (fd_ < 0 || ::flock(fd_, LOCK_EX) != 0) {
      throw std::runtime_error(fmt::format("{}: cannot lock the runner cache", path.string()));
    }
  }
  BuildLock(const BuildLock&) = delete;
  BuildLock& operator=(const BuildLock&) = delete;
  ~BuildLock() { ::close(fd_); }

 private:
  int fd_;
};

fs::path cache_root(const runtime::DataDir& data) {
  if (const char* dir = std::getenv("FLANGE_COSIM_CACHE"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  return data.runner_cache;
}

// The runner links the project's archives, so it is compiled like them: with the build's C++
// compiler, and in a sanitizer build (FLANGE_SANITIZE, scripts/reliability.sh) with its
// sanitizers, whose runtime those archives need.
constexpr const char* kRunnerCompiler = FLANGE_RUNNER_CXX;
std::string runner_sanitize_flags() {
  const std::string sanitizers = FLANGE_RUNNER_SANITIZE;
  return sanitizers.empty() ? "" : "-fsanitize=" + sanitizers + " -fno-sanitize-recover=all";
}

// ccache for the runner's compiler when the one found at build time is still there.
std::vector<std::string> compiler_cache_environment() {
  const fs::path ccache = FLANGE_CCACHE;
  std::error_code ignored;
  if (ccache.empty() || std::getenv("OBJCACHE") != nullptr || !fs::exists(ccache, ignored)) {
    return {};
  }
  return {"OBJCACHE=" + ccache.string()};
}

}  // namespace

fs::path ensure_verilated_runner(const fs::path& filter_json, std::ostream& log) {
  const fs::path set_dir = fs::absolute(filter_json).parent_path();
  const fs::path package = set_dir / "iir_coeffs_pkg.sv";
  const fs::path rom = set_dir / "coeffs.mem";
  for (const fs::path& f : {package, rom}) {
    if (!fs::is_regular_file(f)) {
      throw std::invalid_argument(fmt::format("{}: missing (it must sit beside {})", f.string(),
                                              filter_json.filename().string()));
    }
  }
  // The runner for this set: RTL, package and ROM image, and the runner's own code.
  const runtime::DataDir data = runtime::data_dir();
  const fs::path& root = data.root;
  const std::vector<fs::path> rtl = {root / "rtl/iir_mac.sv", root / "rtl/iir_core.sv"};
  const std::vector<fs::path> runner_sources = {root / "tb/cosim_main.cpp",
                                                root / "tb/iir_core_dut.cpp"};
  const std::vector<fs::path>& libs = data.runner_archives;
  std::uint64_t key = 0xcbf29ce484222325ull;
  for (const auto* group : {&rtl, &runner_sources, &libs}) {
    for (const fs::path& f : *group) key = fnv1a(key, read_file(f));
  }
  key = fnv1a(key, read_file(package));
  key = fnv1a(key, read_file(rom));
  key = fnv1a(key, kRunnerCompiler + std::string(" ") + runner_sanitize_flags());
  const fs::path dir =
      cache_root(data) / fmt::format("{}-{:016x}", set_dir.filename().string(), key);
  const fs::path runner = dir / "obj" / "flange_cosim_runner";

  // Tests and users may ask for the same runner at once: one builds, the others wait on the lock
  // and find the finished runner (never a half-linked one).
  fs::create_directories(dir);
  const BuildLock lock(dir / "build.lock");
  if (!fs::exists(runner)) {
    // The ROM image is copied in, so the runner does not depend on where the set lives.
    fs::copy_file(rom, dir / "coeffs.mem", fs::copy_options::overwrite_existing);
    log << "building the Verilated core for " << set_dir.filename().string() << " in "
        << dir.string() << " (once per set)\n";
    std::vector<std::string> cmd = {verilator_program(),
                                    "--cc",
                                    "--exe",
                                    "--build",
                                    "-j",
                                    "2",
                                    "--Mdir",
                                    (dir / "obj").string(),
                                    "--top-module",
                                    "iir_core",
                                    "--prefix",
                                    "Viir_core",
                                    "--trace-fst",
                                    "--assert",
                                    "-O3",
                                    fmt::format("-GRomFile=\"{}\"", (dir / "coeffs.mem").string()),
                                    package.string()};
    for (const fs::path& f : rtl) cmd.push_back(f.string());
    for (const fs::path& f : runner_sources) cmd.push_back(f.string());
    cmd.insert(
        cmd.end(),
        {"-CFLAGS",
         fmt::format("-std=c++20 -O2 -I{} -I{} {}", (root / "tb").string(),
                     (root / "model").string(), runner_sanitize_flags()),
         "-LDFLAGS",
         fmt::format("{} {} -lfmt {}", libs[0].string(), libs[1].string(),
                     runner_sanitize_flags()),
         "-MAKEFLAGS", fmt::format("CXX={}", kRunnerCompiler), "-MAKEFLAGS",
         fmt::format("LINK={}", kRunnerCompiler), "-o",
         "flange_cosim_runner"});
    const fs::path build_log = dir / "build.log";
    const int status = spawn(cmd, build_log, dir / "build.err", compiler_cache_environment());
    if (status != 0 || !fs::exists(runner)) {
      fs::remove(runner);
      throw std::runtime_error(
          fmt::format("building the Verilated runner failed (status {}); see {} and {}", status,
                      build_log.string(), (dir / "build.err").string()));
    }
  }

  return runner;
}

std::string verilator_program() {
  const fs::path found = FLANGE_VERILATOR_BIN;
  std::error_code ignored;
  return fs::exists(found, ignored) ? found.string() : "verilator";
}

int spawn_with_files(const std::vector<std::string>& argv, const fs::path& out_file,
                     const fs::path& err_file) {
  return spawn(argv, out_file, err_file);
}

std::string read_whole_file(const fs::path& path) { return read_file(path); }

}  // namespace flange::tb
