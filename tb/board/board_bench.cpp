// SPDX-License-Identifier: MIT
// The Verilated Basys-3 top driven pin by pin. The DUT instance is `dut`.
#include "board_bench.h"

#include <Vbasys3_top.h>
#include <verilated.h>
#include <verilated_fst_c.h>

#include "rtl_coverage.h"

namespace flange::tb::board {

struct BoardBench::Impl {
  std::unique_ptr<VerilatedContext> context = std::make_unique<VerilatedContext>();
  std::unique_ptr<Vbasys3_top> dut;
  std::unique_ptr<VerilatedFstC> trace;
  void dump() {
    context->timeInc(1);
    if (trace) trace->dump(context->time());
  }
};

namespace {

// Segment pattern (CA in bit 0, active high) -> character.
char segment_char(unsigned seg) {
  static constexpr unsigned kPatterns[] = {0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07,
                                           0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71};
  static constexpr char kChars[] = "0123456789ABCDEF";
  if (seg == 0) return ' ';
  if (seg == 0x40) return '-';
  for (int i = 0; i < 16; ++i) {
    if (kPatterns[i] == seg) return kChars[i];
  }
  return '?';
}

}  // namespace

BoardBench::BoardBench(const std::filesystem::path& fst_path) : impl_(std::make_unique<Impl>()) {
  impl_->context->fatalOnError(false);
  if (!fst_path.empty()) impl_->context->traceEverOn(true);
  impl_->dut = std::make_unique<Vbasys3_top>(impl_->context.get(), "dut");
  if (!fst_path.empty()) {
    std::filesystem::create_directories(fst_path.parent_path());
    impl_->trace = std::make_unique<VerilatedFstC>();
    impl_->dut->trace(impl_->trace.get(), 99);
    impl_->trace->open(fst_path.string().c_str());
  }
  Vbasys3_top& dut = *impl_->dut;
  dut.clk_i = 0;
  dut.uart_rx_i = 1;
  dut.btn_c_i = 0;
  dut.sw_i = 0;
  dut.eval();
  // The power-on reset count: 15 cycles.
  run(32);
}

BoardBench::~BoardBench() {
  if (impl_->trace) impl_->trace->close();
  impl_->dut->final();
  write_rtl_coverage(*impl_->context, "basys3_top");
}

void BoardBench::send(const std::vector<std::uint8_t>& bytes, bool bad_stop) {
  const auto bit_time = [this](bool level) {
    rx_levels_.insert(rx_levels_.end(), kSimClksPerBit, level);
  };
  for (std::uint8_t byte : bytes) {
    bit_time(false);
    for (int bit = 0; bit < 8; ++bit) bit_time(((byte >> bit) & 1u) != 0);
    bit_time(!bad_stop);
  }
}

void BoardBench::idle(int bits) {
  rx_levels_.insert(rx_levels_.end(), static_cast<std::size_t>(bits * kSimClksPerBit), true);
}

void BoardBench::glitch(int cycles) {
  rx_levels_.insert(rx_levels_.end(), static_cast<std::size_t>(cycles), false);
  idle(1);
}

void BoardBench::tick() {
  Vbasys3_top& dut = *impl_->dut;
  dut.uart_rx_i = rx_levels_.empty() ? 1 : (rx_levels_.front() ? 1 : 0);
  dut.sw_i = switches_;
  dut.btn_c_i = button_ ? 1 : 0;
  dut.eval();
  impl_->dump();
  dut.clk_i = 1;
  dut.eval();
  impl_->dump();
  dut.clk_i = 0;
  dut.eval();
  ++cycle_;
  if (!rx_levels_.empty()) rx_levels_.pop_front();

  // The TX pin, decoded like a receiver: the start edge, then the middle of every bit.
  const bool tx = dut.uart_tx_o != 0;
  switch (tx_state_) {
    case TxState::kIdle:
      if (!tx) {
        tx_state_ = TxState::kBits;
        tx_count_ = kSimClksPerBit / 2;
        tx_bit_ = 0;
        tx_shift_ = 0;
      }
      break;
    case TxState::kBits:
      if (--tx_count_ == 0) {
        tx_shift_ = static_cast<std::uint16_t>(tx_shift_ | (tx ? 1u : 0u) << tx_bit_);
        tx_count_ = kSimClksPerBit;
        if (++tx_bit_ == 10) {
          const bool start_ok = (tx_shift_ & 1u) == 0;
          tx_bytes_.push_back({static_cast<std::uint8_t>((tx_shift_ >> 1) & 0xFFu),
                               start_ok && (tx_shift_ >> 9) != 0});
          tx_state_ = TxState::kIdle;
        }
      }
      break;
  }
  tx_idle_cycles_ =
      (tx && tx_state_ == TxState::kIdle && rx_levels_.empty()) ? tx_idle_cycles_ + 1 : 0;

  // The display: exactly one anode low selects the digit the segments belong to.
  const unsigned an = ~static_cast<unsigned>(dut.an_no) & 0xFu;
  for (int d = 0; d < 4; ++d) {
    if (an == (1u << d)) {
      std::string text(1, segment_char(~static_cast<unsigned>(dut.seg_no) & 0x7Fu));
      if (dut.dp_no == 0) text += '.';
      digits_[d] = text;
    }
  }
}

void BoardBench::run(std::uint64_t cycles) {
  for (std::uint64_t i = 0; i < cycles; ++i) tick();
}

void BoardBench::drain(int quiet_bits) {
  const auto quiet = static_cast<std::uint64_t>(quiet_bits * kSimClksPerBit);
  while (sending() || tx_idle_cycles_ < quiet) tick();
}

void BoardBench::press_reset() {
  set_button(true);
  run(64);
  set_button(false);
  run(64);
}

std::uint16_t BoardBench::leds() const { return impl_->dut->led_o; }

std::string BoardBench::display() const {
  return digits_[3] + digits_[2] + digits_[1] + digits_[0];
}

bool BoardBench::assertion_failed() const { return impl_->context->gotError(); }

}  // namespace flange::tb::board
