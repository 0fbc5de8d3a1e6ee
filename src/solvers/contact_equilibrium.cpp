// contact_equilibrium.cpp: the rod's equilibrium resting on touchable obstacles
// (contact_equilibrium.hpp). Stages: the free solve; the contact set from its penetrations; per
// contact set a Newton solve of the patches' conditions; the set's update; the accuracy check.
#include "rodshape/solvers/contact_equilibrium.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <variant>

#include "rodshape/error.hpp"
#include "rodshape/solvers/shooting_residual.hpp"

namespace rodshape {

namespace {

/// One patch of the contact set on one obstacle: a point contact at s = a (reaction Pa), or a
/// segment [a, b] lying on a plane of the obstacle (normal ν), with point reactions Pa, Pb at
/// its ends inside the rod. A point contact at a free tip (at_tip, a = b = L) rests the tip on
/// the obstacle at an angle: its reaction joins the tip's wrench and only g(L) = 0 is asked.
struct Patch {
  int obstacle = -1;
  bool point = false;
  bool at_tip = false;      // a point contact at the free tip
  bool from_clamp = false;  // a = 0: the clamp lies on the plane (it takes the end's reaction)
  bool to_tip = false;      // b = L: the tip lies on it (a held tip takes the end's reaction)
  double a = 0.0, b = 0.0, Pa = 0.0, Pb = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // ν of the plane (segments)
  bool free_a() const { return !point && !from_clamp; }
  bool free_b() const { return !point && !to_tip; }
};

/// What stays fixed over one Newton solve.
struct Setup {
  const ClampedRod& rod;
  const TipCondition& tip;
  const Scene& scene;
  double radius;  // the section's radius when it is not known
  bool free_tip;
  int* integrations;  // the solve's count of rod integrations
};

RodPoint node_point(const RodConfiguration& c, int i) {
  const std::size_t k = static_cast<std::size_t>(i);
  RodPoint point;
  point.s = c.s[k];
  point.p = c.p[k];
  point.R = c.R[k];
  point.n = c.n[k];
  point.m = c.m[k];
  point.p_prime = point.R * c.v[k];
  point.u = c.u[k];
  return point;
}

/// The section's support distance along ν (radius when unknown).
double support(const RodProperties& properties,
               const Eigen::Matrix3d& R,
               const Eigen::Vector3d& nu,
               double radius) {
  if (!properties.section) return radius;
  const CrossSection& section = *properties.section;
  if (section.shape == CrossSection::Shape::Circle) return section.radius;
  return 0.5 * section.width * std::abs(R.col(0).dot(nu)) +
         0.5 * section.height * std::abs(R.col(1).dot(nu));
}

/// g' at a point: ∇d·p' less the support's rate (by central differences along the rod's own
/// rotation rate, for a rectangle).
double gap_rate(const Obstacle& o, const RodPoint& x, const RodProperties& properties, double r) {
  const PointDistance d = o.distance(x.p);
  double rate = d.gradient.dot(x.p_prime);
  if (properties.section && properties.section->shape == CrossSection::Shape::Rectangle &&
      x.u.norm() > 0.0) {
    const double e = 1e-6 * properties.length;
    const auto h_at = [&](double t) {
      const Eigen::Matrix3d R = x.R * Eigen::AngleAxisd(t * x.u.norm(), x.u.normalized()).matrix();
      return support(properties, R, o.distance(x.p + t * x.p_prime).gradient, r);
    };
    rate -= (h_at(e) - h_at(-e)) / (2.0 * e);
  }
  return rate;
}

/// The line reaction that carries a segment lying on a plane: λ = -f·ν (the load pressing on it;
/// with it, a rod on the plane with n·ν = 0 and no moment about ν × t stays on it: exact for a
/// Kirchhoff rod, and for a Cosserat rod, whose shear along ν is then 0).
double lying_reaction(const ClampedRod& rod, const Patch& p) {
  return -rod.load.force.dot(p.normal);
}

/// The unknowns' layout: z = (w, then each patch's own: a point (s, P); a segment (a, Pa) unless
/// from the clamp, (b, Pb) unless to the tip).
int unknowns_of(const std::vector<Patch>& patches) {
  int n = 6;
  for (const Patch& p : patches) n += p.at_tip ? 1 : p.point ? 2 : 2 * p.free_a() + 2 * p.free_b();
  return n;
}

/// The conditions' count: the tip's six, a point's two (g, g'; at the tip g), a segment's four at a
/// free a (g, g', n·ν and m·(ν × t) after a) or two at the clamp (n·ν, m·(ν × t)). A segment to a
/// held tip repeats two of the tip's: the system is then solved in least squares.
int conditions_of(const std::vector<Patch>& patches) {
  int n = 6;
  for (const Patch& p : patches) n += p.at_tip ? 1 : p.point ? 2 : (p.from_clamp ? 2 : 4);
  return n;
}

Eigen::VectorXd pack(const BaseWrench& w, const std::vector<Patch>& patches) {
  Eigen::VectorXd z(unknowns_of(patches));
  z << w.force, w.moment, Eigen::VectorXd::Zero(z.size() - 6);
  int k = 6;
  for (const Patch& p : patches) {
    if (p.at_tip)
      z[k++] = p.Pa;
    else if (p.point || p.free_a())
      z[k++] = p.a, z[k++] = p.Pa;
    if (p.free_b()) z[k++] = p.b, z[k++] = p.Pb;
  }
  return z;
}

BaseWrench unpack(const Eigen::VectorXd& z, std::vector<Patch>& patches) {
  int k = 6;
  for (Patch& p : patches) {
    if (p.at_tip)
      p.Pa = z[k++];
    else if (p.point || p.free_a())
      p.a = z[k++], p.Pa = z[k++];
    if (p.free_b()) p.b = z[k++], p.Pb = z[k++];
    if (p.point) p.b = p.a;
  }
  return {z.segment<3>(0), z.segment<3>(3)};
}

/// The unknowns' scales: bending units for w, EI/L² for P, L for s; and which are places.
Eigen::VectorXd scales_of(const ClampedRod& rod,
                          const std::vector<Patch>& patches,
                          std::vector<bool>& place) {
  const RodProperties& rp = rod.properties;
  const double L = rp.length, EI = 0.5 * (rp.K_rot.x() + rp.K_rot.y());
  Eigen::VectorXd scale(unknowns_of(patches));
  place.assign(static_cast<std::size_t>(scale.size()), false);
  scale.head<6>() = rp.bending_wrench_units();
  int k = 6;
  const auto end = [&](bool with_place) {
    if (with_place) place[static_cast<std::size_t>(k)] = true, scale[k++] = L;
    scale[k++] = EI / (L * L);
  };
  for (const Patch& p : patches) {
    if (p.at_tip) end(false);
    if (p.at_tip) continue;
    if (p.point || p.free_a()) end(true);
    if (p.free_b()) end(true);
  }
  return scale;
}

/// The patches' reactions as loads on the rod.
ContactLoads loads_of(const Setup& setup, const std::vector<Patch>& patches) {
  ContactLoads loads;
  for (const Patch& p : patches) {
    if (p.at_tip) continue;  // in the tip's wrench (tip_with_reactions)
    const Obstacle* o = &setup.scene.obstacles[static_cast<std::size_t>(p.obstacle)];
    const auto point = [&](double s, double P) {
      PointForce f;
      f.s = s, f.normal_of = o, f.magnitude = P;
      if (!p.point) f.normal_of = nullptr, f.force = P * p.normal;
      loads.point_forces.push_back(f);
    };
    if (p.point || p.free_a()) point(p.a, p.Pa);
    if (p.free_b()) point(p.b, p.Pb);
    if (p.point) continue;
    LineForce f;
    f.s0 = p.a, f.s1 = p.b;
    f.f0 = f.f1 = lying_reaction(setup.rod, p) * p.normal;
    loads.line_forces.push_back(f);
  }
  return loads;
}

/// The places whose states the conditions read: each point's s and each segment's free a.
std::vector<double> probes_of(const std::vector<Patch>& patches) {
  std::vector<double> s;
  for (const Patch& p : patches) {
    if (p.at_tip) continue;  // read at the last node
    if (p.point || p.free_a()) s.push_back(p.a);
    if (p.free_b()) s.push_back(p.b);
  }
  return s;
}

/// One evaluation of the conditions at z.
struct Evaluation {
  Eigen::VectorXd r;
  RodConfiguration configuration;
  std::vector<RodPointPair> ends;  // probes_of(patches)'s states
  std::vector<Patch> patches;      // unpacked
  BaseWrench w;
};

/// The two conditions that keep a rod on a plane from a point on: n·ν = 0 and m·(ν × t) = 0.
void on_plane(const RodPoint& x, const Eigen::Vector3d& nu, Eigen::VectorXd& r, int& k) {
  const Eigen::Vector3d t = x.p_prime.normalized();
  r[k++] = x.n.dot(nu);           // N
  r[k++] = x.m.dot(nu.cross(t));  // N·m
}

/// The tip condition with the reactions of the point contacts at a free tip added to its wrench.
TipCondition tip_with_reactions(const Setup& setup,
                                const std::vector<Patch>& patches,
                                const RodConfiguration& c) {
  TipCondition tip = setup.tip;
  for (const Patch& p : patches) {
    if (!p.at_tip) continue;
    const Obstacle& o = setup.scene.obstacles[static_cast<std::size_t>(p.obstacle)];
    std::get<FreeTip>(tip).wrench.force += p.Pa * o.distance(c.p.back()).gradient;
  }
  return tip;
}

Evaluation evaluate(const Setup& setup,
                    const std::vector<Patch>& layout,
                    const Eigen::VectorXd& z) {
  Evaluation e;
  e.patches = layout;
  e.w = unpack(z, e.patches);
  ++*setup.integrations;
  integrate_with_contact_loads(setup.rod, e.w, loads_of(setup, e.patches), e.configuration,
                               probes_of(e.patches), &e.ends);
  e.r.resize(conditions_of(e.patches));
  e.r.head<6>() =
      shooting_residual(tip_with_reactions(setup, e.patches, e.configuration), e.configuration);
  const RodProperties& rp = setup.rod.properties;
  const double r = setup.radius;
  int k = 6;
  std::size_t probe = 0;
  for (const Patch& p : e.patches) {
    const Obstacle& o = setup.scene.obstacles[static_cast<std::size_t>(p.obstacle)];
    if (p.at_tip) {
      e.r[k++] = contact_gap(o, node_point(e.configuration, e.configuration.nodes() - 1), rp, r);
      continue;
    }
    if (p.point) {
      const RodPointPair& x = e.ends[probe++];
      e.r[k++] = contact_gap(o, x.before, rp, r);
      e.r[k++] = 0.5 * (gap_rate(o, x.before, rp, r) + gap_rate(o, x.after, rp, r));
      continue;
    }
    if (p.from_clamp) {
      on_plane(node_point(e.configuration, 0), p.normal, e.r, k);
    } else {  // touch-down: tangent on the free side, then on the plane's manifold
      const RodPointPair& x = e.ends[probe++];
      e.r[k++] = contact_gap(o, x.before, rp, r);
      e.r[k++] = gap_rate(o, x.before, rp, r);
      on_plane(x.after, p.normal, e.r, k);
    }
    if (p.free_b()) ++probe;
  }
  return e;
}

/// A layout Newton may evaluate: every segment's ends in order inside the rod.
bool ordered(const std::vector<Patch>& patches, double L) {
  for (const Patch& p : patches)
    if (!(p.a >= 0.0 && p.b <= L && (p.point || p.b - p.a > 1e-9 * L))) return false;
  return true;
}

/// The Jacobian of the conditions in the scaled unknowns and its row scales, kept from one Newton
/// solve to the next while the contact set's layout stays (the load's steps) and updated by
/// Broyden's rank-one formula between central-difference evaluations.
struct JacobianMemory {
  Eigen::MatrixXd J;
  Eigen::VectorXd row_scale;
  std::vector<Patch> layout;

  bool fits(const std::vector<Patch>& patches) const {
    if (J.size() == 0 || patches.size() != layout.size()) return false;
    for (std::size_t i = 0; i < patches.size(); ++i) {
      const Patch &p = patches[i], &q = layout[i];
      if (p.obstacle != q.obstacle || p.point != q.point || p.at_tip != q.at_tip ||
          p.from_clamp != q.from_clamp || p.to_tip != q.to_tip)
        return false;
    }
    return true;
  }
};

/// ∂r/∂z · diag(scale) by central differences (2 evaluations a column).
Eigen::MatrixXd central_jacobian(const Setup& setup,
                                 const std::vector<Patch>& layout,
                                 const Eigen::VectorXd& z,
                                 const Eigen::VectorXd& scale,
                                 int m) {
  Eigen::MatrixXd J(m, z.size());
  for (int j = 0; j < z.size(); ++j) {
    Eigen::VectorXd plus = z, minus = z;
    const double dz = 1e-6 * scale[j];
    plus[j] += dz, minus[j] -= dz;
    J.col(j) = (evaluate(setup, layout, plus).r - evaluate(setup, layout, minus).r) / (2.0 * dz) *
               scale[j];
  }
  return J;
}

/// Gauss–Newton in the scaled unknowns (square, or with more conditions than unknowns where a
/// segment reaches a held tip), rows equilibrated by the first central-difference Jacobian, with
/// backtracking on the scaled residual; each end moved at most one interval a step. The Jacobian
/// is `memory`'s when it fits the layout, updated by Broyden's formula J += (Δr - J Δx) Δxᵀ/|Δx|²
/// after each accepted step; a step it cannot make is retried with a fresh central-difference
/// Jacobian.
bool newton(const Setup& setup,
            const std::vector<Patch>& layout,
            Eigen::VectorXd& z,
            Evaluation& at,
            double tolerance,
            int max_iterations,
            int& iterations,
            JacobianMemory& memory) {
  std::vector<bool> place;
  const Eigen::VectorXd scale = scales_of(setup.rod, layout, place);
  const double L = setup.rod.properties.length, h = setup.rod.step();
  const int n = static_cast<int>(z.size());
  at = evaluate(setup, layout, z);
  const int m = static_cast<int>(at.r.size());
  bool fresh = false;
  const auto refresh = [&] {
    memory.J = central_jacobian(setup, layout, z, scale, m);
    memory.row_scale.resize(m);
    for (int i = 0; i < m; ++i)
      memory.row_scale[i] = 1.0 / std::max(memory.J.row(i).cwiseAbs().maxCoeff(), 1e-300);
    memory.layout = layout;
    fresh = true;
  };
  if (!memory.fits(layout) || memory.J.rows() != m || memory.J.cols() != n) refresh();
  for (int it = 0; it < max_iterations; ++it) {
    if (!at.r.allFinite()) return false;
    if (at.r.lpNorm<Eigen::Infinity>() <= tolerance) return true;
    const auto D = memory.row_scale.asDiagonal();
    const Eigen::VectorXd step = (D * memory.J).colPivHouseholderQr().solve(-(D * at.r));
    Eigen::VectorXd dz = step.cwiseProduct(scale);
    if (!dz.allFinite()) return false;
    for (int j = 6; j < n; ++j)
      if (place[static_cast<std::size_t>(j)] && std::abs(dz[j]) > h) dz *= h / std::abs(dz[j]);
    const double merit = (D * at.r).squaredNorm();
    bool accepted = false;
    for (double t = 1.0; t > 1e-4; t *= 0.5) {
      Eigen::VectorXd trial = z + t * dz;
      for (int j = 6; j < n; ++j)
        if (place[static_cast<std::size_t>(j)]) trial[j] = std::clamp(trial[j], 0.0, L);
      std::vector<Patch> check = layout;
      unpack(trial, check);
      if (!ordered(check, L)) continue;
      Evaluation e = evaluate(setup, layout, trial);
      if (e.r.allFinite() && (D * e.r).squaredNorm() < merit) {
        const Eigen::VectorXd dx = (trial - z).cwiseQuotient(scale);
        memory.J += (e.r - at.r - memory.J * dx) * dx.transpose() / dx.squaredNorm();
        z = trial, at = std::move(e), accepted = true, fresh = false;
        break;
      }
    }
    ++iterations;
    if (!accepted) {
      if (fresh) return at.r.lpNorm<Eigen::Infinity>() <= tolerance;
      refresh();
    }
  }
  return at.r.lpNorm<Eigen::Infinity>() <= tolerance;
}

/// Whether a patch of obstacle j covers s (a point contact: within half an interval).
bool covered(const std::vector<Patch>& patches, int j, double s, double h) {
  for (const Patch& p : patches)
    if (p.obstacle == j && s >= p.a - 0.5 * h * p.point && s <= p.b + 0.5 * h * p.point)
      return true;
  return false;
}

/// The gap of node i to obstacle j.
double node_gap(const Setup& setup, const RodConfiguration& c, int j, int i) {
  return contact_gap(setup.scene.obstacles[static_cast<std::size_t>(j)], node_point(c, i),
                     setup.rod.properties, setup.radius);
}

/// Whether the run of nodes i0..i1 is on one plane of obstacle j that the load presses the rod
/// onto (a half-space, or one face of a box): its normal there.
std::optional<Eigen::Vector3d> plane_under(
    const Setup& setup, int j, int i0, int i1, const RodConfiguration& c) {
  const Obstacle& o = setup.scene.obstacles[static_cast<std::size_t>(j)];
  const bool flat = std::holds_alternative<HalfSpaceObstacle>(o.shape) ||
                    std::holds_alternative<BoxObstacle>(o.shape);
  if (!flat || i1 <= i0) return std::nullopt;
  const Eigen::Vector3d nu = o.distance(c.p[static_cast<std::size_t>(i0)]).gradient;
  if ((o.distance(c.p[static_cast<std::size_t>(i1)]).gradient - nu).norm() > 1e-9)
    return std::nullopt;
  if (!(-setup.rod.load.force.dot(nu) > 0.0)) return std::nullopt;
  return nu;
}

/// A new patch on obstacle j over the penetrating run of nodes i0..i1: a segment on the plane
/// under it, half an interval beyond the run (from the clamp when the run starts there), or else
/// a point contact at its deepest node.
Patch new_patch(const Setup& setup, int j, int i0, int i1, const RodConfiguration& c) {
  const double h = setup.rod.step(), L = setup.rod.properties.length;
  const int N = setup.rod.intervals;
  Patch p;
  p.obstacle = j;
  // end reactions start pushing: at P = 0 moving an end and changing its force act alike (the
  // Jacobian is singular there); a quarter of the rod's weight, or 0.1 EI/L² weightless
  const double EI = 0.5 * (setup.rod.properties.K_rot.x() + setup.rod.properties.K_rot.y());
  p.Pa = p.Pb = std::max(0.25 * setup.rod.load.force.norm() * L, 0.1 * EI / (L * L));
  int deepest = i0;
  for (int i = i0; i <= i1; ++i)
    if (node_gap(setup, c, j, i) < node_gap(setup, c, j, deepest)) deepest = i;
  const bool from_clamp = i0 <= 1 && std::abs(node_gap(setup, c, j, 0)) <= 1e-6 * L;
  if (setup.free_tip && deepest == N && !(from_clamp && i1 == N)) {
    // the free tip rests on it, at an angle, first (unless the whole rod goes under: it lies)
    p.point = p.at_tip = true;
    p.a = p.b = L;
    return p;
  }
  const std::optional<Eigen::Vector3d> plane = plane_under(setup, j, std::max(i0, 1), i1, c);
  if (!plane) {
    p.point = true;
    p.a = p.b = std::clamp(deepest, 1, N - 1) * h;
    return p;
  }
  p.normal = *plane;
  p.from_clamp = from_clamp;
  p.to_tip = i1 >= N - 1;
  p.a = p.from_clamp ? 0.0 : (i0 - 0.5) * h;
  p.b = p.to_tip ? L : (i1 + 0.5) * h;
  return p;
}

/// Adds patches for the free spans' penetrating runs of nodes (a run next to a segment's free
/// end extends it); true when any was added or extended.
bool add_penetrations(const Setup& setup,
                      const Evaluation& e,
                      std::vector<Patch>& patches,
                      double tolerance) {
  const RodConfiguration& c = e.configuration;
  const double h = setup.rod.step();
  bool added = false;
  for (int j = 0; j < static_cast<int>(setup.scene.obstacles.size()); ++j) {
    if (!setup.scene.obstacles[static_cast<std::size_t>(j)].touchable()) continue;
    const auto penetrates = [&](int i) {
      return i < c.nodes() && !covered(patches, j, i * h, h) &&
             node_gap(setup, c, j, i) < -tolerance;
    };
    for (int i = 0; i < c.nodes(); ++i) {
      if (!penetrates(i)) continue;
      int i1 = i;
      while (penetrates(i1 + 1)) ++i1;
      patches.push_back(new_patch(setup, j, i, i1, c));
      added = true;
      i = i1;
    }
  }
  return added;
}

/// The plane a free tip resting on it at an angle has turned to lie on, if it has: the rod rises
/// towards the tip (g'(L) > 0), so that the nodes behind it would go under.
std::optional<Eigen::Vector3d> plane_the_tip_lies_on(const Setup& setup,
                                                     const Evaluation& e,
                                                     const Patch& p) {
  const RodConfiguration& c = e.configuration;
  const int N = c.nodes() - 1;
  const std::optional<Eigen::Vector3d> plane = plane_under(setup, p.obstacle, N - 1, N, c);
  const Obstacle& o = setup.scene.obstacles[static_cast<std::size_t>(p.obstacle)];
  if (plane && gap_rate(o, node_point(c, N), setup.rod.properties, setup.radius) > 0.0)
    return plane;
  return std::nullopt;
}

/// One update of the contact set; true when it changed: a reaction that pulls drops its patch (a
/// segment becomes a point contact at its middle), an end that reaches the clamp or the tip
/// stays there, and penetrations of the free spans add patches.
bool update_contact_set(const Setup& setup,
                        const Evaluation& e,
                        std::vector<Patch>& patches,
                        double gap_tolerance) {
  const double force_tolerance = 1e-9 * setup.rod.properties.bending_wrench_units()[0];
  const double L = setup.rod.properties.length;
  std::vector<Patch> next;
  bool changed = false;
  for (Patch p : e.patches) {
    if (p.point && p.Pa < -force_tolerance) {
      changed = true;
      continue;
    }
    if (const auto plane = p.at_tip ? plane_the_tip_lies_on(setup, e, p) : std::nullopt) {
      p.point = p.at_tip = false, p.to_tip = true;
      p.a = L - setup.rod.step(), p.normal = *plane;
      changed = true;
    }
    if (!p.point) {
      if (p.free_b() && p.b >= L * (1.0 - 1e-9)) p.to_tip = true, p.b = L, changed = true;
      if (setup.free_tip && p.to_tip && p.free_a() && p.Pa < -force_tolerance) {
        p.point = p.at_tip = true,
        p.to_tip = false;  // the free tip rises off: it rests at an angle
        p.a = p.b = L, p.Pa = std::abs(p.Pa);
        changed = true;
      } else if ((p.free_a() && p.Pa < -force_tolerance) ||
                 (p.free_b() && p.Pb < -force_tolerance)) {
        p.point = true, p.from_clamp = p.to_tip = false;
        p.a = p.b = 0.5 * (p.a + p.b), p.Pa = 0.0;
        changed = true;
      }
    }
    next.push_back(p);
  }
  patches = std::move(next);
  if (changed) return true;
  return add_penetrations(setup, e, patches, gap_tolerance);
}

/// The contacts of the solved patches: each one's span, its end reactions, its line reaction
/// (constant along ν on a segment) and its whole reaction.
std::vector<RodContact> contacts_of(const Setup& setup, const Evaluation& e) {
  std::vector<RodContact> contacts;
  std::size_t probe = 0;
  for (const Patch& p : e.patches) {
    const Obstacle& o = setup.scene.obstacles[static_cast<std::size_t>(p.obstacle)];
    RodContact c;
    c.obstacle = p.obstacle;
    c.s_start = p.a;
    c.s_end = p.b;
    if (p.at_tip) {
      c.start_force = p.Pa;
      c.force = p.Pa * o.distance(e.configuration.p.back()).gradient;
    } else if (p.point) {
      c.start_force = p.Pa;
      c.force = p.Pa * o.distance(e.ends[probe++].before.p).gradient;
    } else {
      c.start_force = p.free_a() ? p.Pa : 0.0;
      c.end_force = p.free_b() ? p.Pb : 0.0;
      c.max_line_force = lying_reaction(setup.rod, p);
      c.force = (c.start_force + c.end_force + c.max_line_force * (p.b - p.a)) * p.normal;
      probe += static_cast<std::size_t>(p.free_a()) + static_cast<std::size_t>(p.free_b());
    }
    contacts.push_back(c);
  }
  return contacts;
}

/// The least gap to the touchable obstacles at the nodes and the contact ends.
double least_touch_gap(const Setup& setup, const Evaluation& e) {
  double least = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : setup.scene.obstacles) {
    if (!o.touchable()) continue;
    for (int i = 0; i < e.configuration.nodes(); ++i)
      least = std::min(least, contact_gap(o, node_point(e.configuration, i), setup.rod.properties,
                                          setup.radius));
    for (const RodPointPair& x : e.ends)
      least = std::min(least, contact_gap(o, x.after, setup.rod.properties, setup.radius));
  }
  return least;
}

/// |Δp|/L over the nodes between the rod and one with twice the sub-steps, at the same unknowns.
double integration_error(const Setup& setup, const Evaluation& e) {
  ClampedRod fine = setup.rod;
  fine.substeps *= 2;
  RodConfiguration c;
  ++*setup.integrations;
  integrate_with_contact_loads(fine, e.w, loads_of(setup, e.patches), c);
  double error = 0.0;
  for (int i = 0; i < c.nodes(); ++i)
    error = std::max(
        error,
        (c.p[static_cast<std::size_t>(i)] - e.configuration.p[static_cast<std::size_t>(i)]).norm() /
            setup.rod.properties.length);
  return error;
}

/// The clamp and a held tip with the rod's surface outside every touchable obstacle (to 1e-9 m):
/// a pose inside one is bad input, naming the pose and the obstacle.
void check_held_poses(const Setup& setup) {
  const auto check = [&](const Pose& pose, const std::string& field) {
    RodPoint x;
    x.p = pose.position, x.R = pose.rotation;
    for (std::size_t j = 0; j < setup.scene.obstacles.size(); ++j) {
      const Obstacle& o = setup.scene.obstacles[j];
      const double gap = contact_gap(o, x, setup.rod.properties, setup.radius);
      if (o.touchable() && gap < -1e-9)
        throw InputError(field, " puts the rod " + std::to_string(-gap * 1e3) +
                                    " mm inside obstacle " + o.label(static_cast<int>(j)) +
                                    " (Scene.obstacles[" + std::to_string(j) + "])");
    }
  };
  check(setup.rod.clamp, "ClampedRod.clamp");
  if (const auto* clamped = std::get_if<ClampedTip>(&setup.tip))
    check(clamped->pose, "ClampedTip.pose");
  if (const auto* grasped = std::get_if<GraspedTip>(&setup.tip))
    check(grasped->pose, "GraspedTip.pose");
}

bool touches_nothing(const Scene& scene) {
  return std::none_of(scene.obstacles.begin(), scene.obstacles.end(),
                      [](const Obstacle& o) { return o.touchable(); });
}

/// The active-set loop at one load: Newton on the contact set, then its update, until it is
/// consistent (true) or Newton fails or the passes run out (false; `patches` and `at` as they
/// were then).
bool settle(const Setup& setup,
            std::vector<Patch>& patches,
            Evaluation& at,
            const ShootingOptions& options,
            const ContactOptions& contact,
            ContactEquilibriumResult& result,
            JacobianMemory& memory) {
  for (int pass = 0; pass < contact.max_active_set_iterations; ++pass) {
    ++result.active_set_iterations;
    Eigen::VectorXd z = pack(at.w, patches);
    if (!newton(setup, patches, z, at, options.residual_tolerance, contact.max_newton_iterations,
                result.newton_iterations, memory))
      return false;
    if (!update_contact_set(setup, at, patches, contact.gap_tolerance)) return true;
  }
  return false;
}

/// The load scaled from 0 (the free equilibrium of the weightless rod) to the rod's own, the
/// contact set settled at each step from the last; steps halved on failure down to 1/1024.
bool follow_load(const Setup& full,
                 std::vector<Patch>& patches,
                 Evaluation& at,
                 const ShootingOptions& options,
                 const ContactOptions& contact,
                 ContactEquilibriumResult& result) {
  ClampedRod scaled = full.rod;
  JacobianMemory memory;
  double alpha = 0.0, step = 1.0 / 16.0;
  while (alpha < 1.0) {
    const double next = std::min(1.0, alpha + step);
    scaled.load.force = next * full.rod.load.force;
    scaled.load.moment = next * full.rod.load.moment;
    const Setup setup{scaled, full.tip, full.scene, full.radius, full.free_tip, full.integrations};
    std::vector<Patch> trial_patches = patches;
    Evaluation trial = at;
    JacobianMemory trial_memory = memory;
    if (settle(setup, trial_patches, trial, options, contact, result, trial_memory)) {
      alpha = next, patches = std::move(trial_patches), at = std::move(trial);
      memory = std::move(trial_memory);
      step = std::min(2.0 * step, 0.5);
    } else if ((step *= 0.5) < 1.0 / 1024.0) {
      at = std::move(trial);
      return false;
    }
  }
  return true;
}

/// Whether a rectangular section touches an obstacle tilted about its tangent (neither of its
/// axes along the normal), at a node within 1e-6 L of it: it rests on a corner of its section,
/// where the reaction acts off the centreline, which is not solved.
bool on_a_corner(const Setup& setup, const RodConfiguration& c) {
  const auto& section = setup.rod.properties.section;
  if (!section || section->shape != CrossSection::Shape::Rectangle) return false;
  for (int j = 0; j < static_cast<int>(setup.scene.obstacles.size()); ++j) {
    const Obstacle& o = setup.scene.obstacles[static_cast<std::size_t>(j)];
    if (!o.touchable()) continue;
    for (int i = 0; i < c.nodes(); ++i) {
      if (std::abs(node_gap(setup, c, j, i)) > 1e-6 * setup.rod.properties.length) continue;
      const Eigen::Vector3d nu = o.distance(c.p[static_cast<std::size_t>(i)]).gradient;
      const Eigen::Matrix3d& R = c.R[static_cast<std::size_t>(i)];
      if (std::min(std::abs(R.col(0).dot(nu)), std::abs(R.col(1).dot(nu))) > 1e-6) return true;
    }
  }
  return false;
}

/// The last stage: the followed state as the result, its contacts, and its status (Converged only
/// when the load was followed to the end and the integration error is within tolerance).
void report(const Setup& setup,
            const Evaluation& at,
            bool followed,
            const ShootingOptions& options,
            ContactEquilibriumResult& result) {
  ShootingSummary& summary = result.shooting.summary;
  result.shooting.base_wrench = at.w;
  result.shooting.configuration = at.configuration;
  summary.iterations += result.newton_iterations;
  if (at.r.size()) summary.residual_norm = at.r.lpNorm<Eigen::Infinity>();
  result.least_gap = least_touch_gap(setup, at);
  result.contacts = contacts_of(setup, at);
  if (!followed) {
    summary.status = SolveStatus::Diverged;
    summary.message = "the contact conditions were not solved as the load was applied (|r| = " +
                      std::to_string(summary.residual_norm) + ")";
    if (on_a_corner(setup, at.configuration))
      summary.message +=
          ": the rectangular section rests on a corner of its section (tilted about its tangent), "
          "where the reaction acts off the centreline; that is not solved (docs/limits.md)";
    return;
  }
  summary.integration_error = integration_error(setup, at);
  summary.substeps = setup.rod.substeps;
  if (!(summary.integration_error <= options.integration_tolerance)) {
    summary.status = SolveStatus::DiscretisationTooCoarse;
    summary.message = "the contact equilibrium's integration error " +
                      std::to_string(summary.integration_error) + " exceeds the tolerance";
    return;
  }
  summary.status = SolveStatus::Converged;
  summary.message = "converged with " + result.brief();
}

}  // namespace

void ContactOptions::validate() const {
  if (max_active_set_iterations < 1 || max_active_set_iterations > kMaxActiveSetIterations)
    throw InputError("ContactOptions.max_active_set_iterations",
                     " = " + std::to_string(max_active_set_iterations) + " must be in [1, " +
                         std::to_string(kMaxActiveSetIterations) + "]");
  if (max_newton_iterations < 1 || max_newton_iterations > kMaxNewtonIterations)
    throw InputError("ContactOptions.max_newton_iterations",
                     " = " + std::to_string(max_newton_iterations) + " must be in [1, " +
                         std::to_string(kMaxNewtonIterations) + "]");
  if (!(gap_tolerance > 0.0 && gap_tolerance <= 1e-3))
    throw InputError("ContactOptions.gap_tolerance", " must be in (0, 1e-3] m");
}

double contact_gap(const Obstacle& obstacle,
                   const RodPoint& point,
                   const RodProperties& properties,
                   double radius) {
  const PointDistance d = obstacle.distance(point.p);
  return d.distance - support(properties, point.R, d.gradient, radius);
}

std::string ContactEquilibriumResult::brief() const {
  double largest = 0.0;
  for (const RodContact& c : contacts) largest = std::max(largest, c.force.norm());
  std::ostringstream out;
  out << contacts.size() << (contacts.size() == 1 ? " contact" : " contacts");
  if (!contacts.empty()) out << ", largest reaction " << largest << " N";
  return out.str();
}

ContactEquilibriumResult solve_contact_equilibrium(const ClampedRod& rod,
                                                   const TipCondition& tip,
                                                   const Scene& scene,
                                                   const BaseWrench& guess,
                                                   const ShootingOptions& options,
                                                   const ContactOptions& contact) {
  contact.validate();
  scene.validate();
  ContactEquilibriumResult result;
  if (touches_nothing(scene)) {
    result.shooting = solve_equilibrium(rod, tip, guess, options);
    return result;
  }
  int integrations = 0;
  const Setup setup{
      rod, tip, scene, scene.rod_radius, std::holds_alternative<FreeTip>(tip), &integrations};
  check_held_poses(setup);
  std::vector<Patch> patches;
  Evaluation at;
  ShootingSummary& summary = result.shooting.summary;
  // From the weightless rod's free equilibrium.
  ClampedRod weightless = rod;
  weightless.load = {};
  const ShootingResult start = solve_equilibrium(weightless, tip, guess, options);
  if (!start.summary.converged()) {
    summary = start.summary;
    summary.message = "the weightless rod, where contact is followed from: " + summary.message;
    return result;
  }
  at.configuration = start.configuration;
  at.w = start.base_wrench;
  const bool followed = follow_load(setup, patches, at, options, contact, result);
  if (followed && at.patches.empty()) {  // clear of every obstacle: the free solve, refined
    const int passes = result.active_set_iterations, iterations = result.newton_iterations;
    result.shooting = solve_equilibrium(rod, tip, at.w, options);
    result.least_gap = least_touch_gap(setup, at);
    result.active_set_iterations = passes, result.newton_iterations = iterations;
    return result;
  }
  report(setup, at, followed, options, result);
  summary.integrations = start.summary.integrations + integrations;
  summary.jacobian_evaluations = start.summary.jacobian_evaluations;
  return result;
}

}  // namespace rodshape
