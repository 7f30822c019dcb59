// SPDX-License-Identifier: MIT
#include "channel_stream.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "input_error.h"

namespace flange::host {

std::string ReplyChecker::check(int channel, std::int16_t word, const board::Reply& reply) {
  if (reply.status & board::kStatusChannelError) {
    return fmt::format("channel {}: the board has no such channel", channel);
  }
  if (reply.status & board::kStatusBypass) {
    // The board's filter is frozen (sw[0]): the model must not step either.
    if (reply.sample == word) return "";
    return fmt::format("channel {}: bypassed reply {} is not the input {}", channel, reply.sample,
                       word);
  }
  const model::SampleResult want = bank_.step(word, channel);
  const bool saturated = (reply.status & board::kStatusSaturation) != 0;
  if (reply.sample == want.sample && saturated == want.saturated) return "";
  return fmt::format("channel {}: input {} gave {}{}, the model {}{}", channel, word, reply.sample,
                     saturated ? " (saturated)" : "", want.sample,
                     want.saturated ? " (saturated)" : "");
}

int check_channel_numbers(std::span<const int> channels, const ReplyChecker* checker,
                          const std::string& source) {
  if (channels.empty()) throw InputError(source + ": no channels");
  int highest = 0;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (channels[i] < 0 || channels[i] > 255) {
      throw InputError(
          fmt::format("{}: channel {} is outside the link's 0 to 255", source, channels[i]));
    }
    if (std::find(channels.begin(), channels.begin() + i, channels[i]) != channels.begin() + i) {
      throw InputError(fmt::format("{}: channel {} is listed twice", source, channels[i]));
    }
    highest = std::max(highest, channels[i]);
  }
  if (checker && highest >= checker->channels()) {
    throw InputError(
        fmt::format("{}: channel {} is not in the coefficient set, which has channels "
                    "0 to {}",
                    source, highest, checker->channels() - 1));
  }
  return highest;
}

ChannelSession::ChannelSession(BoardLink& link, std::span<const int> channels,
                               ReplyChecker* checker, const std::string& source)
    : link_(link), checker_(checker), several_(channels.size() > 1) {
  const int highest = check_channel_numbers(channels, checker, source);
  board_channels_ = link_.reset_session();
  if (highest >= board_channels_) {
    throw InputError(
        fmt::format("{}: channel {} is not on the board on {}, which serves channels "
                    "0 to {}",
                    source, highest, link_.device(), board_channels_ - 1));
  }
  if (checker_ && checker_->channels() != board_channels_) {
    throw std::runtime_error(fmt::format(
        "the board on {} serves {} channels, the coefficient set {}: not its bitstream's set",
        link_.device(), board_channels_, checker_->channels()));
  }
  sent_.assign(static_cast<std::size_t>(highest) + 1, 0);
  answered_.assign(sent_.size(), 0);
  counts_.channels = channels.size();
  counts_.checked = checker_ != nullptr;
}

void ChannelSession::send(int channel, std::int16_t word, BoardLink::OnReply on_reply) {
  const auto index = static_cast<std::size_t>(channel);
  std::string what = several_ ? fmt::format("sample {} of channel {}", sent_.at(index), channel)
                              : fmt::format("sample {}", sent_.at(index));
  ++sent_[index];
  link_.post(static_cast<std::uint8_t>(channel), word, std::move(what),
             [this, channel, word, on_reply = std::move(on_reply)](const board::Reply& reply) {
               take(channel, word, reply);
               on_reply(reply);
             });
}

void ChannelSession::take(int channel, std::int16_t word, const board::Reply& reply) {
  const auto index = static_cast<std::size_t>(channel);
  ++answered_[index];
  ++counts_.samples;
  counts_.link_errors += (reply.status & board::kStatusLinkError) ? 1 : 0;
  counts_.overruns += (reply.status & board::kStatusOverrun) ? 1 : 0;
  counts_.saturated += (reply.status & board::kStatusSaturation) ? 1 : 0;
  counts_.bypassed += (reply.status & board::kStatusBypass) ? 1 : 0;
  if (!checker_) return;
  const std::string mismatch = checker_->check(channel, word, reply);
  if (mismatch.empty()) return;
  if (counts_.mismatches == 0) {
    counts_.first_mismatch = fmt::format("sample {} of {}", answered_[index] - 1, mismatch);
  }
  ++counts_.mismatches;
}

StreamCounts ChannelSession::counts() const {
  StreamCounts counts = counts_;
  counts.resent = link_.counts().resent;
  counts.stray_replies = link_.counts().stray_replies;
  counts.discarded_bytes = link_.counts().discarded_bytes;
  counts.board_resets = link_.counts().board_resets;
  counts.replayed = link_.counts().replayed;
  counts.false_frames = link_.counts().false_frames;
  return counts;
}

std::vector<std::size_t> round_robin_order(std::span<const std::size_t> lengths) {
  std::vector<std::size_t> order;
  const std::size_t longest =
      lengths.empty() ? 0 : *std::max_element(lengths.begin(), lengths.end());
  for (std::size_t n = 0; n < longest; ++n) {
    for (std::size_t c = 0; c < lengths.size(); ++c) {
      if (n < lengths[c]) order.push_back(c);
    }
  }
  return order;
}

std::vector<ChannelReplies> stream_channels(BoardLink& link, std::span<const ChannelWords> channels,
                                            ReplyChecker* checker, StreamCounts& counts,
                                            const std::string& source) {
  std::vector<int> numbers;
  std::vector<std::size_t> lengths;
  std::vector<ChannelReplies> out;
  for (const ChannelWords& c : channels) {
    numbers.push_back(c.channel);
    lengths.push_back(c.words.size());
    out.push_back({c.channel, {}});
    out.back().replies.reserve(c.words.size());
  }
  ChannelSession session(link, numbers, checker, source);
  std::vector<std::size_t> sent(channels.size(), 0);
  for (std::size_t position : round_robin_order(lengths)) {
    const ChannelWords& c = channels[position];
    std::vector<board::Reply>& replies = out[position].replies;
    session.send(c.channel, c.words[sent[position]++],
                 [&replies](const board::Reply& reply) { replies.push_back(reply); });
  }
  session.finish();
  counts = session.counts();
  return out;
}

std::string stream_summary_line(const StreamCounts& counts) {
  std::string line = fmt::format("stream: {} samples", counts.samples);
  if (counts.channels > 1) line += fmt::format(" of {} channels", counts.channels);
  line += fmt::format(
      " in {:.2f} s, {} resent, {} stray replies, {} discarded bytes; board reported {} link "
      "errors, {} overruns, {} saturated, {} bypassed; {} inputs clipped",
      counts.seconds, counts.resent, counts.stray_replies, counts.discarded_bytes,
      counts.link_errors, counts.overruns, counts.saturated, counts.bypassed,
      counts.clipped_inputs);
  if (counts.board_resets > 0) {
    line += fmt::format(
        "; the board was reset {} time(s), {} samples replayed to rebuild its filters",
        counts.board_resets, counts.replayed);
  }
  if (counts.false_frames > 0) {
    line += fmt::format(
        "; the board took {} damaged request(s) for valid ones, recovered by a replay",
        counts.false_frames);
  }
  if (counts.checked) {
    line += fmt::format("; {} mismatches against the model", counts.mismatches);
    if (counts.mismatches > 0) line += " (first: " + counts.first_mismatch + ")";
  }
  return line;
}

}  // namespace flange::host
