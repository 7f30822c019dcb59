// SPDX-License-Identifier: MIT
// A wheel's forecast input (host/wear/limit_forecast.h, ForecastInput) as the JSON the store's
// wear estimates keep in their `forecast` column (schema version 7, docs/store.md), so the plan
// made from the store is the same quantile of the same forecast as the fresh estimate's: every
// field by name, numbers written with the digits that read back to the same double.
#pragma once

#include <string>

#include "limit_forecast.h"

namespace flange::cli {

std::string forecast_input_json(const host::ForecastInput& input);

// Throws std::invalid_argument naming what is wrong when the text is not such an object (not
// JSON, or a field missing or not a number; null reads as NaN, as a non-finite one is written).
host::ForecastInput forecast_input_of_json(const std::string& text);

}  // namespace flange::cli
