// two_end_path.cpp: both ends' paths on one clock (two_end_path.hpp).
#include "two_end_path.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "rodshape/error.hpp"

namespace rodshape::sim_detail {

namespace {

/// Where `at` lies between `from` and `to` on the segment's line and slerp: σ ∈ [0, 1], from the
/// position when the segment translates, else from the rotation angle.
double progress(const Pose& from, const Pose& to, const Pose& at) {
  const Eigen::Vector3d d = to.position - from.position;
  double sigma = 0.0;
  if (d.squaredNorm() > 0.0) {
    sigma = (at.position - from.position).dot(d) / d.squaredNorm();
  } else {
    const double phi = Eigen::AngleAxisd(from.rotation.transpose() * to.rotation).angle();
    if (phi > 0.0) sigma = Eigen::AngleAxisd(from.rotation.transpose() * at.rotation).angle() / phi;
  }
  return std::clamp(sigma, 0.0, 1.0);
}

/// One segment: `clock` timed by its own limits, `other` following it at the same σ.
std::vector<TimedPose> follow(const std::vector<TimedPose>& clock,
                              const Pose& clock_from,
                              const Pose& clock_to,
                              const Pose& from,
                              const Pose& to) {
  std::vector<TimedPose> path;
  path.reserve(clock.size());
  for (const TimedPose& sample : clock)
    path.push_back({sample.t, interpolate(from, to, progress(clock_from, clock_to, sample.pose))});
  path.front().pose = from;
  path.back().pose = to;
  return path;
}

}  // namespace

TwoEndPath time_two_ends(const std::vector<Pose>& tip,
                         const std::vector<Pose>& base,
                         const EndEffectorLimits& tip_limits,
                         const EndEffectorLimits& base_limits) {
  if (tip.empty() || tip.size() != base.size())
    throw InputError("time_two_ends", ": the two ends need as many waypoints, at least one");
  TwoEndPath path{{{0.0, tip.front()}}, {{0.0, base.front()}}};
  for (std::size_t k = 1; k < tip.size(); ++k) {
    const std::vector<TimedPose> a = time_parameterize({tip[k - 1], tip[k]}, tip_limits);
    const std::vector<TimedPose> b = time_parameterize({base[k - 1], base[k]}, base_limits);
    if (a.size() == 1 && b.size() == 1) continue;  // neither end moves: no time
    const bool tip_clock = a.back().t >= b.back().t;
    const std::vector<TimedPose> other = tip_clock
                                             ? follow(a, tip[k - 1], tip[k], base[k - 1], base[k])
                                             : follow(b, base[k - 1], base[k], tip[k - 1], tip[k]);
    const std::vector<TimedPose>& clock = tip_clock ? a : b;
    const double t0 = path.tip.back().t;
    for (std::size_t j = 1; j < clock.size(); ++j) {
      path.tip.push_back({t0 + clock[j].t, tip_clock ? clock[j].pose : other[j].pose});
      path.base.push_back({t0 + clock[j].t, tip_clock ? other[j].pose : clock[j].pose});
    }
  }
  return path;
}

}  // namespace rodshape::sim_detail
