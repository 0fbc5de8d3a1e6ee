// ros_messages.hpp: the ROS 2 messages rodshape writes (docs/ros.md), their CDR serialisation
// (cdr_writer.hpp, the fields in their .msg order) and their schemas as MCAP's "ros2msg" encoding
// wants them: the type's .msg text, then for each type it uses, once, a line of 80 '=', a line
// "MSG: <package>/<Type>" (as the fields name it) and that type's .msg text
// (github.com/foxglove/mcap, docs/specification/appendix.md, "ros2msg"). The .msg texts are those
// of ROS 2 Humble and Jazzy (ros2/common_interfaces, ros2/rcl_interfaces, ros2/geometry2), without
// their comments.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rodshape {

/// builtin_interfaces/msg/Time and Duration: whole seconds and nanoseconds (0 ≤ nanosec < 1e9).
struct RosTime {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  /// `seconds` rounded to the nanosecond (≥ 0; InputError when negative or beyond int32).
  static RosTime from_seconds(double seconds);
  std::uint64_t nanoseconds() const { return std::uint64_t(sec) * 1000000000ULL + nanosec; }
};

/// std_msgs/msg/Header.
struct RosHeader {
  RosTime stamp;
  std::string frame_id;
};

/// trajectory_msgs/msg/JointTrajectoryPoint.
struct RosJointTrajectoryPoint {
  std::vector<double> positions, velocities, accelerations, effort;
  RosTime time_from_start;
};
/// trajectory_msgs/msg/JointTrajectory.
struct RosJointTrajectory {
  static constexpr std::string_view kType = "trajectory_msgs/msg/JointTrajectory";
  RosHeader header;
  std::vector<std::string> joint_names;
  std::vector<RosJointTrajectoryPoint> points;
};

/// sensor_msgs/msg/JointState.
struct RosJointState {
  static constexpr std::string_view kType = "sensor_msgs/msg/JointState";
  RosHeader header;
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;
};

/// geometry_msgs/msg/TransformStamped: `child_frame_id` in `header.frame_id`.
struct RosTransformStamped {
  RosHeader header;
  std::string child_frame_id;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};
/// tf2_msgs/msg/TFMessage.
struct RosTfMessage {
  static constexpr std::string_view kType = "tf2_msgs/msg/TFMessage";
  std::vector<RosTransformStamped> transforms;
};

/// std_msgs/msg/ColorRGBA.
struct RosColor {
  float r = 0, g = 0, b = 0, a = 1;
};

/// visualization_msgs/msg/Marker (texture, uv_coordinates and mesh_file written empty).
struct RosMarker {
  enum Type : std::int32_t {
    Arrow = 0,
    Cube = 1,
    Sphere = 2,
    Cylinder = 3,
    LineStrip = 4,
    SphereList = 7,
    TextViewFacing = 9,
  };
  RosHeader header;
  std::string ns;
  std::int32_t id = 0;
  std::int32_t type = LineStrip;
  std::int32_t action = 0;  // ADD
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  RosColor color;
  RosTime lifetime;  // 0: forever
  bool frame_locked = false;
  std::vector<Eigen::Vector3d> points;
  std::vector<RosColor> colors;
  std::string text;
};
/// visualization_msgs/msg/MarkerArray.
struct RosMarkerArray {
  static constexpr std::string_view kType = "visualization_msgs/msg/MarkerArray";
  std::vector<RosMarker> markers;
};

/// sensor_msgs/msg/PointField.
struct RosPointField {
  static constexpr std::uint8_t kFloat32 = 7;
  std::string name;
  std::uint32_t offset = 0;
  std::uint8_t datatype = kFloat32;
  std::uint32_t count = 1;
};
/// sensor_msgs/msg/PointCloud2.
struct RosPointCloud2 {
  static constexpr std::string_view kType = "sensor_msgs/msg/PointCloud2";
  RosHeader header;
  std::uint32_t height = 1, width = 0;
  std::vector<RosPointField> fields;
  bool is_bigendian = false;
  std::uint32_t point_step = 0, row_step = 0;
  std::string data;
  bool is_dense = true;
  /// An unorganised cloud (height 1) of float32 x, y, z.
  static RosPointCloud2 xyz(RosHeader header, const std::vector<Eigen::Vector3d>& points);
};

/// The CDR bytes of a message, its encapsulation header first.
std::string ros_cdr(const RosJointTrajectory& message);
std::string ros_cdr(const RosJointState& message);
std::string ros_cdr(const RosTfMessage& message);
std::string ros_cdr(const RosMarkerArray& message);
std::string ros_cdr(const RosPointCloud2& message);

/// The "ros2msg" schema of `type` (one of the kType above, or a type they use, e.g.
/// "geometry_msgs/msg/Pose"); InputError for another.
std::string ros_schema(std::string_view type);

}  // namespace rodshape
