// SPDX-License-Identifier: MIT
// Runs a gnuplot script: every plot the project draws (design responses, run reports) goes
// through here.
#pragma once

#include <string>

namespace flange::coeffs {

// Feeds `script` to gnuplot, its messages to standard error (standard output carries only the
// results); `what` names the output in the error. Throws std::runtime_error
// naming the fix when gnuplot is missing or fails.
void run_gnuplot(const std::string& script, const std::string& what);

}  // namespace flange::coeffs
