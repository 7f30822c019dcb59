// SPDX-License-Identifier: MIT
// The Verilated Basys-3 top (rtl/board/basys3_top.sv) with its pins driven and read like the
// board's: the UART RX pin bit by bit, the TX pin decoded bit by bit, the switches, the centre
// button, the LEDs and the multiplexed 7-segment display.
//
// Each board build (tb/CMakeLists.txt, flange_add_board) has its coefficient set
// (kBoardFilterJson) and ClksPerBit (kSimClksPerBit: 8 for measurement_sos and loco_ch12, so that a
// frame and its reply take about 1100 cycles; 109, the real 921600 baud, for the link-budget build
// of loco_ch12), and RefreshBits = 4
// (a display digit is lit for 4 cycles), DebounceBits = 3, HeartbeatBit = 6. Everything else is
// the synthesised RTL.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace flange::tb::board {

inline constexpr int kSimClksPerBit = FLANGE_BOARD_CLKS_PER_BIT;
inline constexpr const char* kBoardSet = FLANGE_BOARD_SET;
inline constexpr const char* kBoardFilterJson = FLANGE_BOARD_FILTER_JSON;
inline constexpr int kSimRefreshBits = 4;
inline constexpr int kSimHeartbeatBit = 6;

// What one UART frame on the board's TX pin decoded to.
struct TxByte {
  std::uint8_t value = 0;
  bool stop_ok = true;  // the stop bit read high
};

class BoardBench {
 public:
  explicit BoardBench(const std::filesystem::path& fst_path = {});
  ~BoardBench();
  BoardBench(const BoardBench&) = delete;
  BoardBench& operator=(const BoardBench&) = delete;

  // Queues bytes for the RX pin, 8N1 LSB first; `bad_stop` sends a low stop bit (framing error).
  void send(const std::vector<std::uint8_t>& bytes, bool bad_stop = false);
  // Queues `bits` bit times of idle line (high).
  void idle(int bits);
  // Queues a low pulse of `cycles` clock cycles, then one bit time of idle line: shorter than
  // half a bit it is a glitch the receiver must ignore.
  void glitch(int cycles);
  bool sending() const { return !rx_levels_.empty(); }

  // One clock cycle: drives the RX pin, applies the edge, samples TX, LEDs and the display.
  void tick();
  void run(std::uint64_t cycles);
  // Runs until the RX queue is empty and `quiet_bits` bit times passed with TX idle.
  void drain(int quiet_bits = 40);

  // Decoded TX bytes so far (taken by the caller).
  std::deque<TxByte>& received() { return tx_bytes_; }

  void set_switches(std::uint16_t sw) { switches_ = sw; }
  void set_button(bool pressed) { button_ = pressed; }
  // Holds the centre button long enough for the debouncer, then releases it and waits.
  void press_reset();

  std::uint16_t leds() const;
  // The four digits as last scanned, e.g. " 6.00", "-1.99", "14.00" (a '.' after the digit whose
  // dp is lit; '?' for a pattern that is no character). Needs one full refresh after a change.
  std::string display() const;
  std::uint64_t cycle() const { return cycle_; }
  bool assertion_failed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::deque<bool> rx_levels_;  // one entry per clock cycle
  std::uint16_t switches_ = 0;
  bool button_ = false;
  std::uint64_t cycle_ = 0;

  // TX decoder state.
  enum class TxState { kIdle, kBits } tx_state_ = TxState::kIdle;
  int tx_count_ = 0;
  int tx_bit_ = 0;
  std::uint16_t tx_shift_ = 0;
  std::deque<TxByte> tx_bytes_;
  std::uint64_t tx_idle_cycles_ = 0;

  std::string digits_[4];
};

}  // namespace flange::tb::board
