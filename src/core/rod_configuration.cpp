#include "rodshape/core/rod_configuration.hpp"

namespace rodshape {

void RodConfiguration::resize(int nodes, Derivatives with) {
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
}

}  // namespace rodshape
