#include "rodshape/core/rod_configuration.hpp"

#include <cmath>
#include <type_traits>
#include <vector>

namespace rodshape {

namespace {

/// 0 when every entry of `values` is finite, else NaN: x · 0 is 0 for a finite x and NaN for ±inf
/// and NaN, and a NaN in a sum stays. No branch per entry, so the pass is vectorised.
template <class Value>
double zero_if_finite(const std::vector<Value>& values) {
  constexpr Eigen::Index kEntries = [] {
    if constexpr (std::is_same_v<Value, double>)
      return Eigen::Index{1};
    else
      return Eigen::Index{Value::SizeAtCompileTime};
  }();
  const double* first = nullptr;
  if constexpr (std::is_same_v<Value, double>)
    first = values.data();
  else
    first = values.empty() ? nullptr : values.front().data();
  const Eigen::Map<const Eigen::ArrayXd> entries(
      first, kEntries * static_cast<Eigen::Index>(values.size()));
  return (entries * 0.0).sum();
}

}  // namespace

bool RodConfiguration::finite() const {
  if (output == Output::Full && !std::isfinite(energy)) return false;
  const double zero = zero_if_finite(s) + zero_if_finite(p) + zero_if_finite(R) +
                      zero_if_finite(n) + zero_if_finite(m) + zero_if_finite(v) + zero_if_finite(u);
  return zero == 0.0;
}

void RodConfiguration::resize(int nodes, Derivatives with, Output stored) {
  s.resize(nodes);
  p.resize(nodes);
  R.resize(nodes);
  n.resize(nodes);
  m.resize(nodes);
  v.resize(nodes);
  u.resize(nodes);
  const int derivative_nodes = with == Derivatives::AllNodes ? nodes : 0;
  dp_dw.resize(derivative_nodes);
  dtheta_dw.resize(derivative_nodes);
  dn_dw.resize(derivative_nodes);
  dm_dw.resize(derivative_nodes);
  derivatives = with;
  output = stored;
}

}  // namespace rodshape
