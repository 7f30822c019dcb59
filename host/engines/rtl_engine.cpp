// SPDX-License-Identifier: MIT
#include "rtl_engine.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "filter_json.h"
#include "verilated_runner.h"

extern char** environ;

namespace flange::host {
namespace fs = std::filesystem;

namespace {

constexpr unsigned kSaturated = 1u;  // tb/stream_run.h
constexpr unsigned kMismatch = 2u;

void write_all(int fd, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n <= 0) throw std::runtime_error("rtl engine: the Verilated runner stopped reading");
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
}

void read_all(int fd, void* data, std::size_t size) {
  auto* bytes = static_cast<unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(fd, bytes, size);
    if (n <= 0) throw std::runtime_error("rtl engine: the Verilated runner stopped answering");
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
}

class RtlEngine : public FilterEngine {
 public:
  RtlEngine(const std::filesystem::path& filter_json, int channel)
      : gain_(model::load_float_design(filter_json, channel).leftover_gain),
        full_scale_(std::ldexp(1.0, model::load_core_config(filter_json).sample_width - 1)) {
    const fs::path runner = tb::ensure_verilated_runner(filter_json, std::cerr);
    int to_child[2];
    int from_child[2];
    if (::pipe(to_child) != 0 || ::pipe(from_child) != 0) {
      throw std::runtime_error("rtl engine: cannot create pipes");
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, to_child[0], 0);
    posix_spawn_file_actions_adddup2(&actions, from_child[1], 1);
    posix_spawn_file_actions_addclose(&actions, to_child[1]);
    posix_spawn_file_actions_addclose(&actions, from_child[0]);
    const std::string json = fs::absolute(filter_json).string();
    std::vector<std::string> argv_strings = {runner.string(), "--coeffs", json, "--stream",
                                             "--channel", std::to_string(channel)};
    std::vector<char*> argv;
    for (std::string& a : argv_strings) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int rc = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(to_child[0]);
    ::close(from_child[1]);
    to_child_ = to_child[1];
    from_child_ = from_child[0];
    if (rc != 0) throw std::runtime_error("rtl engine: cannot start " + runner.string());
  }

  ~RtlEngine() override {
    const std::uint32_t stop = 0;
    if (::write(to_child_, &stop, sizeof stop) < 0) {
      // The runner is gone already; nothing to stop.
    }
    ::close(to_child_);
    ::close(from_child_);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }

  std::string name() const override { return "rtl"; }

  void process(const std::vector<EngineSample>& in, std::vector<EngineOutput>& out) override {
    out.resize(in.size());
    if (in.empty()) return;
    const auto count = static_cast<std::uint32_t>(in.size());
    std::vector<std::int32_t> words(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) words[k] = in[k].word;
    write_all(to_child_, &count, sizeof count);
    write_all(to_child_, words.data(), words.size() * sizeof(std::int32_t));
    std::vector<unsigned char> reply(in.size() * 5);
    read_all(from_child_, reply.data(), reply.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
      std::int32_t value = 0;
      std::memcpy(&value, &reply[k * 5], 4);
      const unsigned flags = reply[k * 5 + 4];
      if ((flags & kMismatch) != 0) ++mismatches_;
      out[k] = {gain_ * value / full_scale_, (flags & kSaturated) != 0, value};
    }
  }

  std::uint64_t mismatches() const override { return mismatches_; }

 private:
  double gain_;
  double full_scale_;
  pid_t pid_ = 0;
  int to_child_ = -1;
  int from_child_ = -1;
  std::uint64_t mismatches_ = 0;
};

}  // namespace

std::unique_ptr<FilterEngine> make_rtl_engine(const std::filesystem::path& filter_json,
                                              int channel) {
  // A runner that dies mid-run must surface as an error, not kill flange with SIGPIPE.
  ::signal(SIGPIPE, SIG_IGN);
  return std::make_unique<RtlEngine>(filter_json, channel);
}

}  // namespace flange::host
