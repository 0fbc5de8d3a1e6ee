// arm_clearance.cpp: link capsules against obstacles and a rod (the formulas are in
// arm_clearance.hpp).
#include "rodshape/robot/arm_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rodshape/core/segment.hpp"
#include "rodshape/error.hpp"

namespace rodshape {

namespace {

std::string millimetres(double metres) {
  std::ostringstream out;
  out.precision(3);
  out << metres * 1e3 << " mm";
  return out.str();
}

/// The mount's links: those that no joint but the first moves.
constexpr int kMountJoints = 1;

/// Segments of the rod per run (run_balls).
constexpr std::size_t kRun = 8;
/// m: what a run's bound must exceed the best gap by to skip it (far above rounding).
constexpr double kRunSlack = 1e-9;

/// The ball around segments [i, i + kRun) of a rod (their nodes i … i + kRun), thickened by the
/// rod's radius: no point of those segments' capsules lies outside it.
struct RunBall {
  Eigen::Vector3d centre;
  double radius = 0.0;
};

void run_balls(const RodNodes& rod, double rod_radius, std::vector<RunBall>& out) {
  out.clear();
  for (std::size_t i = 0; i + 1 < rod.size(); i += kRun) {
    const std::size_t last = std::min(i + kRun, rod.size() - 1);
    Eigen::Vector3d lower = rod[i], upper = rod[i];
    for (std::size_t k = i + 1; k <= last; ++k) {
      lower = lower.cwiseMin(rod[k]);
      upper = upper.cwiseMax(rod[k]);
    }
    RunBall ball;
    ball.centre = 0.5 * (lower + upper);
    for (std::size_t k = i; k <= last; ++k)
      ball.radius = std::max(ball.radius, (rod[k] - ball.centre).norm());
    ball.radius = ball.radius * (1.0 + 1e-12) + rod_radius;
    out.push_back(ball);
  }
}

/// m: what least_gap's prefilter adds to the least margin so far (far above rounding, far below
/// any gap that matters).
constexpr double kPrefilterSlack = 1e-9;

}  // namespace

ArmClearance::ArmClearance(const ArmModel& arm,
                           const Pose& world_T_base,
                           const Scene& scene,
                           const Eigen::VectorXd& q_mount)
    : arm_(arm), world_T_base_(world_T_base), scene_(scene) {
  scene_.validate();
  arm_.check_joint_positions(q_mount, "q_mount");
  const std::vector<LinkCapsule>& capsules = arm_.link_capsules();
  const std::size_t m = scene_.obstacles.size();
  required_.assign(capsules.size() * m, scene_.clearance);
  mount_.assign(capsules.size() * m, false);
  checks_rod_.assign(capsules.size(), true);
  for (std::size_t c = 0; c < capsules.size(); ++c)
    checks_rod_[c] = arm_.joints_moving_frame(capsules[c].frame) < arm_.joints();
  // The mount: the gaps of the links that (almost) do not move, where the arm stands.
  LinkFrames frames;
  for_each_pair(q_mount, {}, nullptr, std::numeric_limits<double>::infinity(), frames,
                [&](const Measured& x) {
                  const int f = capsules[static_cast<std::size_t>(x.gap.capsule)].frame;
                  if (x.gap.obstacle >= 0 && arm_.joints_moving_frame(f) <= kMountJoints) {
                    double& required = required_[static_cast<std::size_t>(x.gap.capsule) * m +
                                                 static_cast<std::size_t>(x.gap.obstacle)];
                    if (x.gap.gap < required) {
                      required = x.gap.gap;
                      mount_[static_cast<std::size_t>(x.gap.capsule) * m +
                             static_cast<std::size_t>(x.gap.obstacle)] = true;
                    }
                  }
                });
}

bool ArmClearance::is_mount(const LinkGap& gap) const {
  return gap.obstacle >= 0 &&
         mount_[static_cast<std::size_t>(gap.capsule) * scene_.obstacles.size() +
                static_cast<std::size_t>(gap.obstacle)];
}

double ArmClearance::required_gap(int c, int j) const {
  return required_[static_cast<std::size_t>(c) * scene_.obstacles.size() +
                   static_cast<std::size_t>(j)];
}

template <typename Visit>
void ArmClearance::for_each_pair(const Eigen::VectorXd& q,
                                 const std::vector<const RodNodes*>& rods,
                                 const std::vector<Obstacle>* others,
                                 const double& prefilter,
                                 LinkFrames& frames,
                                 Visit&& visit) const {
  const std::vector<LinkCapsule>& capsules = arm_.link_capsules();
  if (capsules.empty()) return;
  arm_.link_frames(q, frames);
  // Each rod's runs of kRun segments in a ball (centre, radius: the segments' own balls inside it),
  // measured once for all the capsules.
  thread_local std::vector<std::vector<RunBall>> runs;
  runs.resize(rods.size());
  for (std::size_t r = 0; r < rods.size(); ++r)
    if (rods[r] != nullptr) run_balls(*rods[r], scene_.rod_radius, runs[r]);
  const Eigen::Matrix3d& R_wb = world_T_base_.rotation;
  const Eigen::Vector3d& p_wb = world_T_base_.position;
  for (std::size_t c = 0; c < capsules.size(); ++c) {
    const LinkCapsule& capsule = capsules[c];
    const Pose& base_T_link = frames.frames[static_cast<std::size_t>(capsule.frame)];
    const Eigen::Vector3d a_base = base_T_link.rotation * capsule.from + base_T_link.position;
    const Eigen::Vector3d b_base = base_T_link.rotation * capsule.to + base_T_link.position;
    const Eigen::Vector3d a = R_wb * a_base + p_wb, b = R_wb * b_base + p_wb;
    const auto report = [&](const SegmentDistance& d, int obstacle, int segment, double required) {
      Measured x;
      x.gap.gap = d.distance - capsule.radius;
      x.gap.margin = x.gap.gap - required;
      x.gap.capsule = static_cast<int>(c);
      x.gap.obstacle = obstacle;
      (obstacle == kOtherArm ? x.gap.other_capsule : x.gap.rod_segment) = segment;
      x.point = a_base + d.t * (b_base - a_base);
      x.gradient = R_wb.transpose() * d.gradient;
      visit(x);
    };
    for (std::size_t j = 0; j < scene_.obstacles.size(); ++j) {
      const SegmentDistance d = scene_.obstacles[j].distance(a, b);
      report(d, static_cast<int>(j), -1, required_gap(static_cast<int>(c), static_cast<int>(j)));
    }
    if (others != nullptr) {
      // A pair whose bounding balls are farther apart than the prefilter is skipped: the segment
      // lies within |b - a|/2 of its midpoint, so |m - m_j| - h - h_j - r_j bounds d from below.
      const Eigen::Vector3d mid = 0.5 * (a + b);
      const double half = 0.5 * (b - a).norm();
      for (std::size_t j = 0; j < others->size(); ++j) {
        const auto& other = std::get<CapsuleObstacle>((*others)[j].shape);
        const double bound = (0.5 * (other.from + other.to) - mid).norm() - half -
                             0.5 * (other.to - other.from).norm() - other.radius;
        if (bound > prefilter + capsule.radius) continue;
        const SegmentDistance d = (*others)[j].distance(a, b);
        report(d, kOtherArm, static_cast<int>(j), scene_.clearance);
      }
    }
    if (!checks_rod_[c]) continue;
    for (std::size_t r = 0; r < rods.size(); ++r) {
      const RodNodes* rod = rods[r];
      if (rod == nullptr || rod->size() < 2) continue;
      // The nearest segment of the rod; segments whose bounding ball is farther than the best so
      // far (or than the prefilter) are skipped.
      double best = prefilter + capsule.radius;  // d is the distance to the rod's surface
      SegmentDistance nearest;
      int nearest_segment = -1;
      Obstacle segment_obstacle{"", CapsuleObstacle{}};
      auto& shape = std::get<CapsuleObstacle>(segment_obstacle.shape);
      shape.radius = scene_.rod_radius;
      for (std::size_t i = 0; i + 1 < rod->size(); ++i) {
        if (i % kRun == 0) {
          // A run whose ball lies farther than the best so far holds no segment that could be
          // nearer (each would be skipped below, or measured and not taken): skip it whole.
          const RunBall& run = runs[r][i / kRun];
          if (distance_to_segment(run.centre, a, b) - run.radius > best + kRunSlack) {
            i += kRun - 1;
            continue;
          }
        }
        const Eigen::Vector3d& p0 = (*rod)[i];
        const Eigen::Vector3d& p1 = (*rod)[i + 1];
        const Eigen::Vector3d mid = 0.5 * (p0 + p1);
        const double ball = 0.5 * (p1 - p0).norm() + scene_.rod_radius;
        if (distance_to_segment(mid, a, b) - ball > best) continue;
        shape.from = p0;
        shape.to = p1;
        const SegmentDistance d = segment_obstacle.distance(a, b);
        if (d.distance <= best) {
          best = d.distance;
          nearest = d;
          nearest_segment = static_cast<int>(i);
        }
      }
      if (nearest_segment >= 0) report(nearest, -1, nearest_segment, scene_.clearance);
    }
  }
}

LinkGap ArmClearance::least_gap(const Eigen::VectorXd& q,
                                const std::vector<const RodNodes*>& rods,
                                const std::vector<Obstacle>* others) const {
  LinkGap least;
  thread_local LinkFrames frames;  // reused: no allocation once sized
  // The rod's and the other arm's pairs (required gap: the clearance) whose gap is bounded below
  // by more than the least margin so far plus the clearance cannot be less (the prefilter skips
  // them, a hair wider than needed so that rounding never skips one that would count): the same
  // least pair as measuring every one.
  double prefilter = std::numeric_limits<double>::infinity();
  for_each_pair(q, rods, others, prefilter, frames, [&](const Measured& x) {
    // The mount's own gap is not news: it counts only when it sinks deeper.
    if (is_mount(x.gap) && x.gap.clear()) return;
    if (x.gap.margin < least.margin) {
      least = x.gap;
      prefilter = least.margin + scene_.clearance + kPrefilterSlack;
    }
  });
  return least;
}

void ArmClearance::near_pairs(const Eigen::VectorXd& q,
                              const std::vector<const RodNodes*>& rods,
                              double influence,
                              std::vector<LinkGapRow>& rows,
                              const std::vector<Obstacle>* others) const {
  rows.clear();
  thread_local LinkFrames frames;  // reused: no allocation once sized
  thread_local Eigen::Matrix<double, 3, Eigen::Dynamic> J;
  for_each_pair(q, rods, others, scene_.clearance + influence, frames, [&](const Measured& x) {
    if (x.gap.margin >= influence || is_mount(x.gap)) return;
    const int f = arm_.link_capsules()[static_cast<std::size_t>(x.gap.capsule)].frame;
    arm_.point_jacobian(frames, f, x.point, J);
    rows.push_back({influence - x.gap.margin, J.transpose() * x.gradient});
  });
}

std::string ArmClearance::describe(const LinkGap& gap, const ArmModel* other) const {
  if (gap.capsule < 0) return "no link measured";
  const std::string link =
      "link " + arm_.link_capsules()[static_cast<std::size_t>(gap.capsule)].label();
  std::string what;
  if (gap.obstacle >= 0)
    what =
        "obstacle " + scene_.obstacles[static_cast<std::size_t>(gap.obstacle)].label(gap.obstacle);
  else if (gap.obstacle == kOtherArm)
    what = "the other arm's link " +
           (other != nullptr
                ? other->link_capsules()[static_cast<std::size_t>(gap.other_capsule)].label()
                : std::to_string(gap.other_capsule));
  else
    what = "the rod";
  return link + ", " + what + ", gap " + millimetres(gap.gap) + " (required " +
         millimetres(gap.gap - gap.margin) + ")";
}

std::vector<Obstacle> world_capsules(const ArmModel& arm,
                                     const Pose& world_T_base,
                                     const Eigen::VectorXd& q) {
  std::vector<Obstacle> capsules;
  const std::vector<LinkCapsule>& links = arm.link_capsules();
  if (links.empty()) return capsules;
  LinkFrames frames;
  arm.link_frames(q, frames);
  capsules.reserve(links.size());
  for (const LinkCapsule& link : links) {
    const Pose world_T_link =
        compose(world_T_base, frames.frames[static_cast<std::size_t>(link.frame)]);
    CapsuleObstacle shape;
    shape.from = world_T_link.rotation * link.from + world_T_link.position;
    shape.to = world_T_link.rotation * link.to + world_T_link.position;
    shape.radius = link.radius;
    capsules.push_back(Obstacle{link.label(), shape});
  }
  return capsules;
}

LinkGap arm_arm_gap(const ArmModel& a,
                    const Pose& world_T_a,
                    const Eigen::VectorXd& q_a,
                    const ArmModel& b,
                    const Pose& world_T_b,
                    const Eigen::VectorXd& q_b,
                    double required) {
  LinkGap least;
  const std::vector<Obstacle> ours = world_capsules(a, world_T_a, q_a);
  const std::vector<Obstacle> theirs = world_capsules(b, world_T_b, q_b);
  for (std::size_t c = 0; c < ours.size(); ++c) {
    const auto& capsule = std::get<CapsuleObstacle>(ours[c].shape);
    const Eigen::Vector3d mid = 0.5 * (capsule.from + capsule.to);
    const double reach = 0.5 * (capsule.to - capsule.from).norm() + capsule.radius;
    for (std::size_t j = 0; j < theirs.size(); ++j) {
      // The bounding balls' gap bounds the pair's from below: skip a pair that cannot be nearer.
      const auto& other = std::get<CapsuleObstacle>(theirs[j].shape);
      const double bound = (0.5 * (other.from + other.to) - mid).norm() - reach -
                           0.5 * (other.to - other.from).norm() - other.radius;
      if (bound - required >= least.margin) continue;
      const double gap = theirs[j].distance(capsule.from, capsule.to).distance - capsule.radius;
      if (gap - required < least.margin) {
        least.gap = gap;
        least.margin = gap - required;
        least.capsule = static_cast<int>(c);
        least.obstacle = kOtherArm;
        least.other_capsule = static_cast<int>(j);
      }
    }
  }
  return least;
}

}  // namespace rodshape
