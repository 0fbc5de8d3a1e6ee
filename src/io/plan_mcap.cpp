// plan_mcap.cpp: plan.mcap and validation.mcap (plan_mcap.hpp; the messages: ros_messages.hpp,
// the container: mcap_writer.hpp).
#include "rodshape/io/plan_mcap.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

#include "rodshape/error.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/ros_messages.hpp"

namespace rodshape {

namespace {

constexpr std::string_view kMcapWorldFrame = "world";

/// The messages of a file, collected and written in log-time order (stable: a topic's order kept).
class McapRecording {
 public:
  explicit McapRecording(const McapOptions& options)
      : writer_("ros2", generator_signature(), options) {}

  template <typename Message>
  void add(std::string_view topic, double t, const Message& message) {
    messages_.push_back(
        {channel(topic, Message::kType), RosTime::from_seconds(t).nanoseconds(), ros_cdr(message)});
  }

  std::string finish() {
    std::stable_sort(messages_.begin(), messages_.end(),
                     [](const Entry& a, const Entry& b) { return a.time < b.time; });
    for (const Entry& m : messages_) writer_.add_message(m.channel, m.time, m.data);
    return writer_.finish();
  }

 private:
  struct Entry {
    std::uint16_t channel;
    std::uint64_t time;
    std::string data;
  };
  std::uint16_t channel(std::string_view topic, std::string_view type) {
    const auto known = channels_.find(std::string(topic));
    if (known != channels_.end()) return known->second;
    auto schema = schemas_.find(std::string(type));
    if (schema == schemas_.end())
      schema =
          schemas_.emplace(std::string(type), writer_.add_schema(type, "ros2msg", ros_schema(type)))
              .first;
    const std::uint16_t id = writer_.add_channel(schema->second, topic, "cdr");
    channels_.emplace(std::string(topic), id);
    return id;
  }
  McapWriter writer_;
  std::map<std::string, std::uint16_t> schemas_, channels_;
  std::vector<Entry> messages_;
};

RosHeader ros_header(double t, std::string_view frame = kMcapWorldFrame) {
  return {RosTime::from_seconds(t), std::string(frame)};
}

RosTransformStamped ros_transform(double t, std::string_view child, const Pose& world_T_child) {
  RosTransformStamped out;
  out.header = ros_header(t);
  out.child_frame_id = std::string(child);
  out.translation = world_T_child.position;
  out.rotation = Eigen::Quaterniond(world_T_child.rotation).normalized();
  return out;
}

/// The clock of the path's samples: the arm's joint trajectory's (re-timed when slowed) when it
/// has every sample, else the path's own.
std::vector<double> mcap_sample_times(const PlanResult& plan) {
  std::vector<double> t;
  const std::vector<TimedPose>& path = plan.end_effector_path;
  if (plan.arm && plan.arm->joints.complete() && plan.arm->joints.t.size() == path.size())
    return plan.arm->joints.t;
  for (const TimedPose& sample : path) t.push_back(sample.t);
  return t;
}

/// The samples of `count` kept: all, or kMaxJointStateMessages spread evenly, ends included.
std::vector<std::size_t> mcap_kept_samples(std::size_t count) {
  std::vector<std::size_t> kept;
  if (count <= kMaxJointStateMessages) {
    for (std::size_t i = 0; i < count; ++i) kept.push_back(i);
    return kept;
  }
  const double stride = static_cast<double>(count - 1) / (kMaxJointStateMessages - 1);
  for (std::size_t k = 0; k < kMaxJointStateMessages; ++k)
    kept.push_back(static_cast<std::size_t>(std::llround(static_cast<double>(k) * stride)));
  return kept;
}

/// The path sample of each step's waypoint, searched forward from the step before's: the first
/// that is the waypoint (the path stops on each, rest to rest: time_parameterize() samples it),
/// else the first nearest to it (distance: position, and rotation angle times the rod's length).
std::vector<std::size_t> mcap_waypoint_samples(const PlanResult& plan, double length) {
  std::vector<std::size_t> samples;
  const std::vector<TimedPose>& path = plan.end_effector_path;
  std::size_t from = 0;
  for (const PlanStep& step : plan.steps) {
    const auto distance = [&](std::size_t i) {
      const Pose& p = path[i].pose;
      const double angle =
          Eigen::AngleAxisd(p.rotation.transpose() * step.end_effector.rotation).angle();
      return (p.position - step.end_effector.position).norm() + length * angle;
    };
    constexpr double kSame = 1e-9;  // m
    std::size_t at = from;
    while (at < path.size() && distance(at) > kSame) ++at;
    if (at == path.size()) {
      at = from;
      for (std::size_t i = from + 1; i < path.size(); ++i)
        if (distance(i) < distance(at)) at = i;
    }
    samples.push_back(at);
    from = at;
  }
  return samples;
}

RosMarker ros_marker(double t, std::string_view ns, int id, RosMarker::Type type, RosColor color) {
  RosMarker m;
  m.header = ros_header(t);
  m.ns = std::string(ns);
  m.id = id;
  m.type = type;
  m.color = color;
  return m;
}

/// The rotation taking z to `axis` (a unit vector).
Eigen::Quaterniond z_axis_to(const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis);
}

RosMarker obstacle_marker(double t, int id, const Obstacle& obstacle, const Pose& clamp) {
  const RosColor grey{0.55F, 0.55F, 0.6F, 0.5F};
  RosMarker m = ros_marker(t, "obstacles", id, RosMarker::Cube, grey);
  m.text = obstacle.name;
  std::visit(
      [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<Shape, SphereObstacle>) {
          m.type = RosMarker::Sphere;
          m.position = shape.center;
          m.scale = Eigen::Vector3d::Constant(2.0 * shape.radius);
        } else if constexpr (std::is_same_v<Shape, BoxObstacle>) {
          m.position = shape.center;
          m.orientation = Eigen::Quaterniond(shape.rotation).normalized();
          m.scale = shape.size;
        } else if constexpr (std::is_same_v<Shape, CapsuleObstacle>) {
          const Eigen::Vector3d axis = shape.to - shape.from;
          m.type = RosMarker::Cylinder;  // its end caps not drawn
          m.position = 0.5 * (shape.from + shape.to);
          m.orientation =
              axis.norm() > 0.0 ? z_axis_to(axis.normalized()) : Eigen::Quaterniond::Identity();
          m.scale = {2.0 * shape.radius, 2.0 * shape.radius, axis.norm()};
        } else {  // a half-space: a 4 m square slab 1 cm thick on its boundary, under the clamp
          const Eigen::Vector3d n = shape.normal.normalized();
          const double offset = shape.offset / shape.normal.norm();
          const Eigen::Vector3d on_plane = clamp.position - (n.dot(clamp.position) - offset) * n;
          m.position = on_plane + 0.005 * n;  // inside the obstacle, n·p > offset
          m.orientation = z_axis_to(n);
          m.scale = {4.0, 4.0, 0.01};
        }
      },
      obstacle.shape);
  return m;
}

/// The scene at `t`: the rod through `nodes`, the target, `objective` and the obstacles.
RosMarkerArray rod_markers(double t,
                           const std::vector<Eigen::Vector3d>& nodes,
                           const std::vector<Eigen::Vector3d>& objective,
                           const PlanProblem& problem) {
  RosMarkerArray array;
  const double radius = problem.scene.rod_radius > 0.0 ? problem.scene.rod_radius : 0.0025;
  RosMarker rod = ros_marker(t, "rod", 0, RosMarker::LineStrip, {0.12F, 0.47F, 0.71F, 1.0F});
  rod.points = nodes;
  rod.scale = {2.0 * radius, 0.0, 0.0};  // a line strip's width is scale.x
  array.markers.push_back(std::move(rod));
  const double point_size = std::max(4.0 * radius, 0.005);
  RosMarker target = ros_marker(t, "target", 0, RosMarker::SphereList, {0.84F, 0.15F, 0.16F, 1.0F});
  target.points = problem.target.points;
  target.scale = Eigen::Vector3d::Constant(point_size);
  array.markers.push_back(std::move(target));
  RosMarker goal = ros_marker(t, "objective", 0, RosMarker::SphereList, {1.0F, 0.5F, 0.05F, 0.8F});
  goal.points = objective;
  goal.scale = Eigen::Vector3d::Constant(0.6 * point_size);
  array.markers.push_back(std::move(goal));
  for (std::size_t i = 0; i < problem.scene.obstacles.size(); ++i)
    array.markers.push_back(
        obstacle_marker(t, static_cast<int>(i), problem.scene.obstacles[i], problem.rod.clamp));
  return array;
}

RosJointTrajectory joint_trajectory_message(const JointTrajectoryResult& joints) {
  RosJointTrajectory message;  // stamp 0: "start when received"
  message.joint_names = joints.joint_names;
  const double t0 = joints.t.empty() ? 0.0 : joints.t.front();
  for (std::size_t i = 0; i < joints.t.size() && i < joints.q.size(); ++i) {
    RosJointTrajectoryPoint point;
    point.positions.assign(joints.q[i].data(), joints.q[i].data() + joints.q[i].size());
    if (i < joints.qdot.size())
      point.velocities.assign(joints.qdot[i].data(), joints.qdot[i].data() + joints.qdot[i].size());
    point.time_from_start = RosTime::from_seconds(joints.t[i] - t0);
    message.points.push_back(std::move(point));
  }
  return message;
}

void add_joint_states(McapRecording& file,
                      std::string_view topic,
                      const JointTrajectoryResult& joints) {
  for (const std::size_t i : mcap_kept_samples(std::min(joints.t.size(), joints.q.size()))) {
    RosJointState state;
    state.header = ros_header(joints.t[i], "");
    state.name = joints.joint_names;
    state.position.assign(joints.q[i].data(), joints.q[i].data() + joints.q[i].size());
    if (i < joints.qdot.size())
      state.velocity.assign(joints.qdot[i].data(), joints.qdot[i].data() + joints.qdot[i].size());
    file.add(topic, joints.t[i], state);
  }
}

void add_plan_topics(McapRecording& file, const PlanResult& plan, const PlanProblem& problem) {
  const std::vector<TimedPose>& path = plan.end_effector_path;
  if (path.empty())
    throw InputError("plan.mcap: the plan has no end-effector path (" + plan.message + ")");
  const std::vector<double> times = mcap_sample_times(plan);
  const bool moving_base = !plan.base_end_effector_path.empty();
  for (const std::size_t i : mcap_kept_samples(path.size())) {
    const double t = times[i];
    RosTfMessage tf;
    const Pose clamp = moving_base
                           ? compose(plan.base_end_effector_path[i].pose,
                                     inverse(problem.moving_base->grasp.tip_to_end_effector))
                           : problem.rod.clamp;
    tf.transforms.push_back(ros_transform(t, "clamp", clamp));
    tf.transforms.push_back(
        ros_transform(t, "tip", compose(path[i].pose, inverse(problem.grasp.tip_to_end_effector))));
    if (problem.arm) {
      tf.transforms.push_back(ros_transform(t, "base", problem.arm->placement.world_T_base));
      tf.transforms.push_back(ros_transform(
          t, "flange", compose(path[i].pose, inverse(problem.arm->placement.flange_T_ee))));
    }
    if (problem.base_arm && moving_base) {
      tf.transforms.push_back(
          ros_transform(t, "base_arm/base", problem.base_arm->placement.world_T_base));
      tf.transforms.push_back(
          ros_transform(t, "base_arm/flange",
                        compose(plan.base_end_effector_path[i].pose,
                                inverse(problem.base_arm->placement.flange_T_ee))));
    }
    file.add("/tf", t, tf);
  }
  if (plan.arm && plan.arm->joints.complete()) {
    file.add("/rodshape/joint_trajectory", times.front(),
             joint_trajectory_message(plan.arm->joints));
    add_joint_states(file, "/joint_states", plan.arm->joints);
  }
  if (plan.base_arm && plan.base_arm->joints.complete()) {
    file.add("/rodshape/base_joint_trajectory", times.front(),
             joint_trajectory_message(plan.base_arm->joints));
    add_joint_states(file, "/base_arm/joint_states", plan.base_arm->joints);  // same joint names
  }
  file.add("/rodshape/rod", times.front(),
           rod_markers(times.front(), plan.initial_configuration.p, plan.initial_points, problem));
  const std::vector<std::size_t> waypoints =
      mcap_waypoint_samples(plan, problem.rod.properties.length);
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    const double t = times[waypoints[k]];
    file.add("/rodshape/rod", t,
             rod_markers(t, plan.steps[k].solution.configuration.p, plan.steps[k].objective_points,
                         problem));
  }
}

}  // namespace

std::string plan_mcap(const PlanResult& plan,
                      const PlanProblem& problem,
                      const McapOptions& options) {
  McapRecording file(options);
  add_plan_topics(file, plan, problem);
  return file.finish();
}

std::string validation_mcap(const ValidationResult& result,
                            const PlanResult& plan,
                            const PlanProblem& problem,
                            const McapOptions& options) {
  McapRecording file(options);
  add_plan_topics(file, plan, problem);
  for (std::size_t r = 0; r < result.runs.size(); ++r) {
    const ValidationRun& run = result.runs[r];
    if (!run.last_cloud.points.empty())
      file.add("/camera/points", run.last_cloud.t,
               RosPointCloud2::xyz(ros_header(run.last_cloud.t), run.last_cloud.points));
    if (!run.last_seen.markers.empty()) {
      RosMarkerArray seen;
      RosMarker m = ros_marker(run.last_seen.t, "run " + std::to_string(r + 1), static_cast<int>(r),
                               RosMarker::SphereList, {0.17F, 0.63F, 0.17F, 1.0F});
      m.scale = Eigen::Vector3d::Constant(0.008);
      for (const std::optional<Eigen::Vector3d>& p : run.last_seen.markers)
        if (p) m.points.push_back(*p);
      seen.markers.push_back(std::move(m));
      file.add("/rodshape/markers_measured", run.last_seen.t, seen);
    }
  }
  return file.finish();
}

}  // namespace rodshape
