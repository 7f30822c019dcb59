// SPDX-License-Identifier: MIT
#include "exit_status.h"

#include <ostream>

#include "design_error.h"
#include "filter_json.h"
#include "input_error.h"
#include "sim_error.h"
#include "store.h"
#include "vivado_report.h"

namespace flange::cli {

namespace {

template <class Error>
bool is(const std::exception& error) {
  return dynamic_cast<const Error*>(&error) != nullptr;
}

struct Row {
  bool (*matches)(const std::exception&);
  int status;
};

// Every exception that is not a failure, with its status; cli/README.md, "Exit status", lists the
// same rows. Anything else (a store that cannot be reached, a file that cannot be written, a
// tool that failed) is 1.
constexpr Row kTable[] = {
    {is<coeffs::DesignRejected>, kExitDefect},       // valid, but unstable or off the spec
    {is<host::InputError>, kExitBadArgument},        // a file's line and field, an option
    {is<coeffs::BadArgument>, kExitBadArgument},     // flange design's options
    {is<sim::BadArgument>, kExitBadArgument},        // a scenario's options, a twin or truth file
    {is<model::FilterJsonError>, kExitBadArgument},  // a coefficient set's filter.json
    {is<tb::VivadoReportError>, kExitBadArgument},   // a Vivado report not in Vivado's layout
    {is<host::StoreUrlError>, kExitBadArgument},     // a store URL that is not one
    {is<std::invalid_argument>, kExitBadArgument},   // an argument a library refused
};

}  // namespace

int exit_status_of(const std::exception& error) {
  if (const auto* option = dynamic_cast<const OptionError*>(&error)) return option->status();
  for (const Row& row : kTable) {
    if (row.matches(error)) return row.status;
  }
  return kExitFailure;
}

OptionError::OptionError(std::string_view option, const std::exception& cause)
    : std::runtime_error(std::string(option) + ": " + cause.what()),
      status_(exit_status_of(cause)) {}

void naming_option(std::string_view option, const std::function<void()>& step) {
  try {
    step();
  } catch (const std::exception& cause) {
    throw OptionError(option, cause);
  }
}

int report_exit(std::string_view command, const std::exception& error, std::ostream& err) {
  err << command << ": " << error.what() << "\n";
  return exit_status_of(error);
}

}  // namespace flange::cli
