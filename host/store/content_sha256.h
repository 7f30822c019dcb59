// SPDX-License-Identifier: MIT
// SHA-256 (OpenSSL) of what a store records as a session's or a run's source: a file's bytes,
// or a text the caller makes canonical. 64 lowercase hex digits.
#pragma once

#include <string>
#include <string_view>

namespace flange::host {

// Throws std::runtime_error naming the file when it cannot be read.
std::string file_sha256(const std::string& path);

std::string text_sha256(std::string_view text);

}  // namespace flange::host
