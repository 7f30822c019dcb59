// SPDX-License-Identifier: MIT
// The `flange` executable.
#include <iostream>
#include <string>
#include <vector>

#include "cli.h"
#include "flange_commit.h"  // FLANGE_COMMIT, written at build time (cmake/FlangeCommit.cmake)

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return flange::cli::run_flange(args, std::cout, std::cerr, FLANGE_COMMIT);
}
