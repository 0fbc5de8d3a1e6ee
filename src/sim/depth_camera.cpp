// depth_camera.cpp: the rod's capsules splatted into the pixels they may cover, each pixel's ray
// cast against them (z-buffer) and against the occluders, then the kept pixels measured with the
// Kinect-like noise (depth_camera.hpp).
#include "rodshape/sim/depth_camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <variant>

#include "rodshape/core/segment.hpp"
#include "rodshape/error.hpp"
#include "wrist_wrench.hpp"

namespace rodshape {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

/// p in the frame `frame_T_world` maps into.
Eigen::Vector3d transformed(const Pose& frame_T_world, const Eigen::Vector3d& p) {
  return frame_T_world.position + frame_T_world.rotation * p;
}

}  // namespace

std::vector<CapsuleObstacle> arm_link_capsules(const PlanArm& arm, const Eigen::VectorXd& q) {
  LinkFrames frames;
  arm.model.link_frames(q, frames);
  std::vector<CapsuleObstacle> capsules;
  for (const LinkCapsule& capsule : arm.model.link_capsules()) {
    const Pose world_T_link =
        compose(arm.placement.world_T_base, frames.frames[static_cast<std::size_t>(capsule.frame)]);
    capsules.push_back({transformed(world_T_link, capsule.from),
                        transformed(world_T_link, capsule.to), capsule.radius});
  }
  return capsules;
}

DepthCamera::DepthCamera(DepthSensorModel model, std::uint64_t seed)
    : model_(std::move(model)), random_(seed) {
  model_.validate();
  fx_ = model_.focal_x();
  fy_ = model_.focal_y();
  cx_ = 0.5 * model_.width;
  cy_ = 0.5 * model_.height;
}

struct DepthCamera::ZBuffer {
  std::vector<double> depth;
  std::vector<int> segment;
  std::vector<int> touched;
  /// The thread's buffer, at least `pixels` large.
  static ZBuffer& of_this_thread(std::size_t pixels) {
    thread_local ZBuffer buffer;
    if (buffer.depth.size() < pixels) {
      buffer.depth.resize(pixels, kNone);
      buffer.segment.resize(pixels, -1);
    }
    return buffer;
  }
  /// Every pixel hit set back to none.
  void clear() {
    for (const int pixel : touched) {
      depth[static_cast<std::size_t>(pixel)] = kNone;
      segment[static_cast<std::size_t>(pixel)] = -1;
    }
    touched.clear();
  }
};

/// The unit ray through the centre of `pixel` (row-major), camera frame (x right, y down, z ahead).
Eigen::Vector3d DepthCamera::ray(int pixel) const {
  const double u = pixel % model_.width + 0.5, v = pixel / model_.width + 0.5;
  return Eigen::Vector3d((u - cx_) / fx_, (v - cy_) / fy_, 1.0).normalized();
}

/// Each segment's capsule into the pixels of its image's bounding box: a ball of radius r at
/// (x, y, z), z > r, projects within f r (1 + |x| / z) / (z − r) of f x / z (and likewise in y).
void DepthCamera::render_rod(const std::vector<Eigen::Vector3d>& nodes, double radius) {
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const Eigen::Vector3d& a = nodes[i];
    const Eigen::Vector3d& b = nodes[i + 1];
    if (std::min(a.z(), b.z()) <= radius + 1e-6) continue;  // at or behind the image plane
    double u0 = kNone, u1 = -kNone, v0 = kNone, v1 = -kNone;
    for (const Eigen::Vector3d& p : {a, b}) {
      const double du = fx_ * radius * (1.0 + std::abs(p.x()) / p.z()) / (p.z() - radius);
      const double dv = fy_ * radius * (1.0 + std::abs(p.y()) / p.z()) / (p.z() - radius);
      const double u = cx_ + fx_ * p.x() / p.z(), v = cy_ + fy_ * p.y() / p.z();
      u0 = std::min(u0, u - du), u1 = std::max(u1, u + du);
      v0 = std::min(v0, v - dv), v1 = std::max(v1, v + dv);
    }
    const int i0 = std::max(0, static_cast<int>(std::floor(u0)));
    const int i1 = std::min(model_.width - 1, static_cast<int>(std::floor(u1)));
    const int j0 = std::max(0, static_cast<int>(std::floor(v0)));
    const int j1 = std::min(model_.height - 1, static_cast<int>(std::floor(v1)));
    const CapsuleObstacle piece{a, b, radius};
    for (int j = j0; j <= j1; ++j)
      for (int k = i0; k <= i1; ++k) {
        const int pixel = j * model_.width + k;
        const double t = shape_ray_hit(piece, origin, ray(pixel));
        double& nearest = z_->depth[static_cast<std::size_t>(pixel)];
        if (!(t < nearest)) continue;
        if (nearest == kNone) z_->touched.push_back(pixel);
        nearest = t;
        z_->segment[static_cast<std::size_t>(pixel)] = static_cast<int>(i);
      }
  }
  std::sort(z_->touched.begin(), z_->touched.end());  // the visible pixels in a fixed order
}

/// The rod's pixels whose ray meets an occluder before the rod, and those out of range, dropped.
void DepthCamera::hide_occluded(const DepthOccluders& occluders, const Pose& camera_T_world) {
  // The occluders in the camera's frame, where every ray starts at the origin.
  std::vector<Obstacle> solids;
  for (const Obstacle& obstacle : occluders.obstacles)
    solids.push_back(transformed(camera_T_world, obstacle));
  for (const CapsuleObstacle& link : occluders.links)
    solids.push_back({"", transformed(camera_T_world, link)});
  visible_.clear();
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (const int pixel : z_->touched) {
    const double t = z_->depth[static_cast<std::size_t>(pixel)];
    const Eigen::Vector3d d = ray(pixel);
    const double z = t * d.z();
    if (z < model_.min_range || z > model_.max_range) continue;
    const bool hidden = std::any_of(solids.begin(), solids.end(), [&](const Obstacle& solid) {
      return solid.ray_hit(origin, d) < t;
    });
    if (!hidden) visible_.push_back({pixel, t, z_->segment[static_cast<std::size_t>(pixel)]});
  }
}

/// A pixel of the rod whose 4-neighbourhood holds a pixel without the rod (or the image's edge).
bool DepthCamera::on_silhouette(int pixel) const {
  const int u = pixel % model_.width, v = pixel / model_.width;
  const auto empty = [&](int du, int dv) {
    const int uu = u + du, vv = v + dv;
    if (uu < 0 || vv < 0 || uu >= model_.width || vv >= model_.height) return true;
    return z_->depth[static_cast<std::size_t>(vv * model_.width + uu)] == kNone;
  };
  return empty(-1, 0) || empty(1, 0) || empty(0, -1) || empty(0, 1);
}

/// The pixel's surface point seen with the DepthNoiseModel, camera frame: depth z + σ_z(z, θ) ε,
/// pixel (u, v) + lateral_pixels (ε_u, ε_v), back-projected.
Eigen::Vector3d DepthCamera::measure(const Hit& hit,
                                     const std::vector<Eigen::Vector3d>& nodes,
                                     double radius) {
  const Eigen::Vector3d d = ray(hit.pixel);
  const Eigen::Vector3d p = hit.t * d;
  // The surface's normal: from the nearest point of the segment's axis to the hit.
  const Eigen::Vector3d& a = nodes[static_cast<std::size_t>(hit.segment)];
  const Eigen::Vector3d& b = nodes[static_cast<std::size_t>(hit.segment) + 1];
  const Eigen::Vector3d ba = b - a;
  const double along = nearest_on_segment(p, a, b);
  const Eigen::Vector3d normal = (p - a - along * ba) / radius;
  const double theta = std::acos(std::clamp(-normal.dot(d), -1.0, 1.0));
  const double z = p.z() + model_.noise.axial_sigma(p.z(), theta) * normal_(random_);
  const double u = cx_ + fx_ * p.x() / p.z() + model_.noise.lateral_pixels * normal_(random_);
  const double v = cy_ + fy_ * p.y() / p.z() + model_.noise.lateral_pixels * normal_(random_);
  return {(u - cx_) / fx_ * z, (v - cy_) / fy_ * z, z};
}

/// A flying pixel: on the ray of a silhouette pixel, uniformly up to kFlyingDepth behind the rod.
Eigen::Vector3d DepthCamera::flying_pixel(const Hit& hit) {
  const Eigen::Vector3d d = ray(hit.pixel);
  const double z0 = hit.t * d.z();
  const double z = std::min(z0 + kFlyingDepth * uniform_(random_), model_.max_range);
  return d * (z / d.z());
}

CloudFrame DepthCamera::observe(const PlantFrame& frame,
                                double rod_radius,
                                const DepthOccluders& occluders) {
  if (!(rod_radius > 0.0) || !std::isfinite(rod_radius))
    throw InputError("Scene.rod_radius", " = " + std::to_string(rod_radius) +
                                             " must be > 0: the depth camera sees the rod's "
                                             "surface, its section's circumscribed radius");
  const Pose camera_T_world = inverse(model_.camera);
  ZBuffer& z = ZBuffer::of_this_thread(static_cast<std::size_t>(model_.width) * model_.height);
  z_ = &z;
  std::vector<Eigen::Vector3d> nodes;
  nodes.reserve(frame.configuration.p.size());
  for (const Eigen::Vector3d& p : frame.configuration.p)
    nodes.push_back(transformed(camera_T_world, p));
  render_rod(nodes, rod_radius);
  hide_occluded(occluders, camera_T_world);

  // `points` of the visible pixels at random (a partial Fisher–Yates shuffle), measured.
  std::vector<Hit> kept = visible_;
  const std::size_t n = std::min<std::size_t>(kept.size(), static_cast<std::size_t>(model_.points));
  for (std::size_t k = 0; k < n; ++k) {
    std::uniform_int_distribution<std::size_t> pick(k, kept.size() - 1);
    std::swap(kept[k], kept[pick(random_)]);
  }
  kept.resize(n);
  std::vector<Hit> silhouette;
  for (const Hit& hit : visible_)
    if (on_silhouette(hit.pixel)) silhouette.push_back(hit);
  const auto outliers =
      silhouette.empty()
          ? std::size_t{0}
          : static_cast<std::size_t>(std::lround(model_.outliers * static_cast<double>(n)));

  CloudFrame cloud;
  cloud.t = frame.t;
  cloud.points.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    Eigen::Vector3d p;
    if (k < n - outliers) {
      p = measure(kept[k], nodes, rod_radius);
    } else {
      std::uniform_int_distribution<std::size_t> pick(0, silhouette.size() - 1);
      p = flying_pixel(silhouette[pick(random_)]);
    }
    cloud.points.push_back(model_.camera.position + model_.camera.rotation * p);
  }
  z.clear();  // clean for the thread's next frame, of any camera
  z_ = nullptr;
  if (model_.wrist)
    cloud.wrist = sim_detail::measured_wrist_wrench(frame, *model_.wrist, random_, normal_);
  return cloud;
}

}  // namespace rodshape
