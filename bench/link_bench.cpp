// SPDX-License-Identifier: MIT
// link_bench (docs/board.md, "Windowed session"; bench/link_bench.sh runs it): samples per second
// of 12 interleaved channels through the windowed host library (host/board_link), a simulated FTDI
// USB-serial chip (tb/board/ftdi_link.h) and the board (its protocol model, or the Verilated
// 12-channel top) over a socket pair (tb/board/socket_stream.h), for one window, baud rate and
// latency timer. Every reply is checked against the model; the line it prints ends with the
// mismatches (0 expected).
//
//   link_bench --window W --baud B --latency-ms L [--seconds S] [--rtl] [--no-ftdi]
//
// The board is the protocol model (tb/board/basys3_top_model.h), which answers at once, so the
// figure is the link's; --rtl puts the Verilated top there instead, slower than a real 921600-baud
// wire (the figure is then the simulator's). --no-ftdi connects the pty to the board at once.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "board_link.h"
#include "channel_stream.h"
#include "filter_json.h"
#include "pty_board.h"
#include "socket_stream.h"

namespace {

using flange::tb::board::FtdiSettings;
using flange::tb::board::PtyBoard;
using flange::tb::board::PtyBoardOptions;
using flange::tb::board::SocketStream;

struct Args {
  int window = 1;
  int baud = 921600;
  int latency_ms = 16;
  double seconds = 1.0;
  bool ftdi = true;
  bool rtl = false;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "link_bench: %s\nusage: link_bench --window 1..32 --baud BAUD --latency-ms 1..255 "
               "[--seconds 0.1..60] [--rtl] [--no-ftdi]\n",
               why.c_str());
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-ftdi" || arg == "--rtl") {
      (arg == "--rtl" ? a.rtl : a.ftdi) = arg == "--rtl";
      continue;
    }
    if (i + 1 >= argc) usage("missing value after " + arg);
    const std::string value = argv[++i];
    if (arg == "--window")
      a.window = std::stoi(value);
    else if (arg == "--baud")
      a.baud = std::stoi(value);
    else if (arg == "--latency-ms")
      a.latency_ms = std::stoi(value);
    else if (arg == "--seconds")
      a.seconds = std::stod(value);
    else
      usage("unknown argument " + arg);
  }
  if (a.window < 1 || a.window > flange::host::kMaxWindow) usage("--window outside 1..32");
  if (a.latency_ms < 1 || a.latency_ms > 255) usage("--latency-ms outside 1..255");
  if (a.seconds < 0.1 || a.seconds > 60) usage("--seconds outside 0.1..60");
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  PtyBoardOptions options;
  options.protocol_model = !args.rtl;
  if (args.ftdi) {
    options.ftdi = FtdiSettings{args.baud, std::chrono::milliseconds(args.latency_ms),
                                std::chrono::microseconds(250)};
  }
  // A socket pair rather than a pty: a pty's hand-over waits for the kernel's work queue, which
  // on the shared machine would be measured instead of the link (socket_stream.h).
  SocketStream port;
  PtyBoard board(port.board_end(), std::move(options));
  flange::host::BoardLink link(port, {args.baud, 1000, 3, args.window});
  const auto config = flange::model::load_core_config(flange::tb::board::kBoardFilterJson);
  flange::host::ReplyChecker checker(config);
  constexpr int kChannels = 12;
  const std::vector<int> channels = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  flange::host::ChannelSession session(link, channels, &checker, "link_bench");
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> word(-20000, 20000);
  const auto start = std::chrono::steady_clock::now();
  const auto stop = start + std::chrono::duration<double>(args.seconds);
  int sent = 0;
  while (std::chrono::steady_clock::now() < stop) {
    session.send(sent % kChannels, static_cast<std::int16_t>(word(rng)),
                 [](const flange::host::board::Reply&) {});
    ++sent;
  }
  session.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const flange::host::StreamCounts counts = session.counts();
  std::printf(
      "%s, window %d, baud %d, latency timer %d ms%s: %llu samples in %.3f s, %.0f "
      "samples/s, %llu resent, %llu mismatches\n",
      args.rtl ? "Verilated top" : "protocol model", args.window, args.baud, args.latency_ms,
      args.ftdi ? "" : " (no FTDI)", static_cast<unsigned long long>(counts.samples), seconds,
      static_cast<double>(counts.samples) / seconds, static_cast<unsigned long long>(counts.resent),
      static_cast<unsigned long long>(counts.mismatches));
  if (board.assertion_failed() || counts.mismatches > 0) return 1;
  return 0;
}
