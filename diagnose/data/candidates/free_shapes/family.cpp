// SPDX-License-Identifier: MIT
#include "family.h"

#include "compensated_sensitivity.h"
#include "heldout_age.h"
#include "ridge_solve.h"

namespace flange::diagnose::free_shapes {

FreeShapeFit LinearFamily::fit(const FreeShapeInputs& in) {
  std::string chosen_on_heldout;
  const int heldout_values =
      in.heldout_age_unknown
          ? 0
          : choose_on_heldout(in.calibration, in.cal_gap_v, in.heldout, in.ho_gap_v,
                              in.no_level_carried, chosen_on_heldout);
  const Eigen::MatrixXd cal = columns(in.calibration);
  const Eigen::Map<const Eigen::VectorXd> gap(in.cal_gap_v.data(),
                                              static_cast<Eigen::Index>(in.cal_gap_v.size()));
  const Eigen::MatrixXd gram = cal.transpose() * cal;
  const Eigen::VectorXd beta =
      values_chosen_on_heldout().value_or(ridge_solve_normal(gram, cal.transpose() * gap));
  FreeShapeFit fit;
  const std::vector<std::string> value_names = names();
  Eigen::MatrixXd told_by = gram;
  Eigen::Index rows = cal.rows();
  if (values_chosen_on_heldout() && values_told_by_heldout()) {
    const Eigen::MatrixXd ho = columns(in.heldout);
    told_by += ho.transpose() * ho;
    rows += ho.rows();
  }
  const Eigen::VectorXd sensitivity = compensated_sensitivity(told_by, rows);
  for (std::size_t j = 0; j < value_names.size(); ++j) {
    fit.params[value_names[j]] = beta(static_cast<Eigen::Index>(j));
    fit.value_sensitivity_v[value_names[j]] = sensitivity(static_cast<Eigen::Index>(j));
  }
  summarise(beta, in.calibration, fit.params);
  fit.search_edges = search_edges();
  fit.free_values = static_cast<int>(value_names.size()) + searched_values();
  fit.description = describe(beta) + chosen_on_heldout;
  fit.heldout_values = heldout_values;
  fit.cal_voltage_v = as_vector(cal * beta);
  fit.heldout_voltage_v = as_vector(columns(in.heldout) * beta);
  if (in.heldout_age_unknown && follows_the_sensors_age()) {
    place_heldout_age(*this, beta, in.calibration.series, in.heldout, in.ho_gap_v, fit);
  }
  return fit;
}

}  // namespace flange::diagnose::free_shapes
