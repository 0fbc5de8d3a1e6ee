// contact_integration.cpp: the rod integrated under contact reactions (contact_loads.hpp).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cosserat_ode.hpp"
#include "rodshape/core/contact_loads.hpp"

namespace rodshape {

namespace {

using detail::OdePoint;
using detail::OdeState;
using detail::Slot;

/// The break points: the nodes, the ends of the line forces, the point forces and the probes
/// within [0, L], sorted, those closer than 1e-12 L merged into the earlier one.
std::vector<double> break_points(const ClampedRod& rod,
                                 const ContactLoads& loads,
                                 const std::vector<double>& probes) {
  const double L = rod.properties.length;
  std::vector<double> s;
  for (int i = 0; i <= rod.intervals; ++i) s.push_back(i == rod.intervals ? L : i * rod.step());
  for (const LineForce& f : loads.line_forces) s.insert(s.end(), {f.s0, f.s1});
  for (const PointForce& f : loads.point_forces) s.push_back(f.s);
  s.insert(s.end(), probes.begin(), probes.end());
  s.erase(std::remove_if(s.begin(), s.end(), [&](double x) { return !(x >= 0.0 && x <= L); }),
          s.end());
  std::sort(s.begin(), s.end());
  std::vector<double> merged;
  for (const double x : s)
    if (merged.empty() || x - merged.back() > 1e-12 * L) merged.push_back(x);
  return merged;
}

/// Σ λ_k(s) over the line forces acting on the step whose middle is `mid`, the rod at p.
Eigen::Vector3d line_force_at(const ContactLoads& loads,
                              double s,
                              double mid,
                              const Eigen::Vector3d& p) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (const LineForce& k : loads.line_forces) {
    if (!(mid >= k.s0 && mid <= k.s1)) continue;
    const double t = k.s1 > k.s0 ? (s - k.s0) / (k.s1 - k.s0) : 0.0;
    if (k.normal_of)
      f += (k.lambda0 + t * (k.lambda1 - k.lambda0)) * k.normal_of->distance(p).gradient;
    else
      f += k.f0 + t * (k.f1 - k.f0);
  }
  return f;
}

class LoadedIntegrator {
 public:
  LoadedIntegrator(const ClampedRod& rod, const ContactLoads& loads)
      : rod_(rod), loads_(loads), ode_(rod) {}

  /// One Runge–Kutta step of length h from s, the load linear over it.
  void step(OdeState& y, double s, double h) {
    const double mid = s + 0.5 * h;
    OdeState k1, k2, k3, k4, stage;
    stage_rate(y, s, mid, k1);
    stage = y + 0.5 * h * k1;
    stage_rate(stage, mid, mid, k2);
    stage = y + 0.5 * h * k2;
    stage_rate(stage, mid, mid, k3);
    stage = y + h * k3;
    stage_rate(stage, s + h, mid, k4);
    y += (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
  }

  /// The state's pose, wrench and rates at s.
  RodPoint point_at(const OdeState& y, double s) {
    OdeState dy;
    OdePoint point;
    stage_rate(y, s, s, dy, &point);
    RodPoint out;
    out.s = s;
    out.p = y.segment<3>(Slot::p);
    out.R = point.R;
    out.n = y.segment<3>(Slot::n);
    out.m = y.segment<3>(Slot::m);
    out.p_prime = point.p_prime;
    out.u = point.u;
    return out;
  }

  /// n(s⁺) = n(s⁻) - Σ F_j over the point forces at s.
  void apply_point_forces(OdeState& y, double s) const {
    const double close = 1e-12 * rod_.properties.length;
    for (const PointForce& f : loads_.point_forces) {
      if (!(std::abs(f.s - s) <= close)) continue;
      const Eigen::Vector3d p = y.segment<3>(Slot::p);
      y.segment<3>(Slot::n) -=
          f.normal_of ? (f.magnitude * f.normal_of->distance(p).gradient).eval() : f.force;
    }
  }

  /// Node i's values from one evaluation of the ODE at s.
  void store_node(const OdeState& y, double s, int i, RodConfiguration& out) {
    OdeState dy;
    OdePoint point;
    stage_rate(y, s, s, dy, &point);
    const std::size_t k = static_cast<std::size_t>(i);
    out.s[k] = s;
    out.p[k] = y.segment<3>(Slot::p);
    out.R[k] = point.R;
    out.n[k] = y.segment<3>(Slot::n);
    out.m[k] = y.segment<3>(Slot::m);
    out.v[k] = point.v;
    out.u[k] = point.u;
  }

 private:
  /// y' with f = the rod's load + the line forces (of the step whose middle is `mid`) at s.
  void stage_rate(const OdeState& y, double s, double mid, OdeState& dy, OdePoint* keep = nullptr) {
    ode_.f = rod_.load.force + line_force_at(loads_, s, mid, y.segment<3>(Slot::p));
    OdePoint point;
    detail::evaluate<true>(ode_, y, dy, keep ? *keep : point);
  }

  const ClampedRod& rod_;
  const ContactLoads& loads_;
  detail::CosseratOde ode_;
};

OdeState start_state(const ClampedRod& rod, const BaseWrench& w) {
  const Eigen::Quaterniond q(rod.clamp.rotation);
  OdeState y;
  y << q.w(), q.x(), q.y(), q.z(), rod.clamp.position, w.force, w.moment, 0.0;
  return y;
}

}  // namespace

void integrate_with_contact_loads(const ClampedRod& rod,
                                  const BaseWrench& base_wrench,
                                  const ContactLoads& loads,
                                  RodConfiguration& out,
                                  const std::vector<double>& probes,
                                  std::vector<RodPointPair>* at_probes) {
  const std::vector<double> s = break_points(rod, loads, probes);
  const double close = 1e-12 * rod.properties.length;
  out.resize(rod.nodes(), Derivatives::None, Output::Full);
  if (at_probes) at_probes->assign(probes.size(), RodPointPair{});
  LoadedIntegrator integrator(rod, loads);
  OdeState y = start_state(rod, base_wrench);
  int node = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const bool is_node = node < rod.nodes() && std::abs(s[k] - node * rod.step()) <= close;
    if (is_node)
      integrator.store_node(y, node == rod.intervals ? rod.properties.length : s[k], node, out),
          ++node;
    const RodPoint before = at_probes ? integrator.point_at(y, s[k]) : RodPoint{};
    integrator.apply_point_forces(y, s[k]);
    if (at_probes)
      for (std::size_t j = 0; j < probes.size(); ++j)
        if (std::abs(probes[j] - s[k]) <= close)
          (*at_probes)[j] = {before, integrator.point_at(y, s[k])};
    if (k + 1 == s.size()) break;
    const double h = (s[k + 1] - s[k]) / rod.substeps;
    for (int j = 0; j < rod.substeps; ++j) integrator.step(y, s[k] + j * h, h);
  }
  out.energy = y[Slot::e];
}

}  // namespace rodshape
