#include "rodshape/core/rod_configuration.hpp"

#include <cmath>

namespace rodshape {

bool RodConfiguration::finite() const {
  if (output == Output::Full && !std::isfinite(energy)) return false;
  for (int i = 0; i < nodes(); ++i) {
    if (!std::isfinite(s[i]) || !p[i].allFinite() || !R[i].allFinite() || !n[i].allFinite() ||
        !m[i].allFinite() || !v[i].allFinite() || !u[i].allFinite())
      return false;
  }
  return true;
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
