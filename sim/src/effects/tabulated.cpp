// SPDX-License-Identifier: MIT
// tabulated: what a table (effect_table.h) adds to the voltage, after every other effect but the
// converter:
// a shape known by its values rather than by a formula, such as the free shape `flange diagnose`
// fitted (its twin.json). The table itself comes from the twin file; its one parameter places the
// table's curve of the sensor's age.
#include <memory>
#include <utility>

#include "effect_catalogue.h"
#include "effects.h"
#include "sim_error.h"

namespace flange::sim {
namespace {

constexpr double kSecondsPerDay = 86400.0;

class Tabulated final : public Effect {
 public:
  Tabulated(const ParamValues& p, std::shared_ptr<const EffectTable> table)
      : table_(std::move(table)), start_age_days_(p.at("start_age_days")) {}

  // At the temperature the channel reports: a table is fitted against recorded temperatures, and
  // behind a lagging or late temperature channel those differ from the ambient.
  void apply(ChainSample& sample) override {
    sample.voltage_v += table_->added_voltage(sample.clearance_mm, sample.thermocouple_c,
                                              start_age_days_ + sample.t_s / kSecondsPerDay);
  }

 private:
  std::shared_ptr<const EffectTable> table_;
  double start_age_days_;
};

}  // namespace

EffectSpec tabulated_effect() {
  EffectSpec spec;
  spec.name = tabulated_effect_name();
  spec.summary = "a table of what is added to the voltage over clearance, temperature and age";
  spec.stage = ChainStage::kAcquisition;
  spec.params = {
      {"start_age_days", 0.0, -3650.0, 3650.0, "days",
       "the sensor's age at the record's start on the table's age axis"},
  };
  spec.make = [](const ParamValues& p, const EffectContext& context) -> std::unique_ptr<Effect> {
    if (!context.table) {
      throw BadArgument("tabulated: the effect needs its table, which only a twin file gives");
    }
    return std::make_unique<Tabulated>(p, context.table);
  };
  return spec;
}

}  // namespace flange::sim
