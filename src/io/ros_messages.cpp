// ros_messages.cpp: the ROS 2 messages' .msg texts and CDR serialisation (ros_messages.hpp).
#include "rodshape/io/ros_messages.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

#include "rodshape/error.hpp"
#include "rodshape/io/cdr_writer.hpp"

namespace rodshape {

namespace {

struct MsgDefinition {
  std::string_view type;
  std::string_view text;
  std::vector<std::string_view> uses;  // the types its fields name, in their order
};

/// The .msg texts (ROS 2 Humble and Jazzy), field for field, constants included.
const std::vector<MsgDefinition>& msg_definitions() {
  static const std::vector<MsgDefinition> table = {
      {"builtin_interfaces/msg/Time", "int32 sec\nuint32 nanosec\n", {}},
      {"builtin_interfaces/msg/Duration", "int32 sec\nuint32 nanosec\n", {}},
      {"std_msgs/msg/Header",
       "builtin_interfaces/Time stamp\nstring frame_id\n",
       {"builtin_interfaces/msg/Time"}},
      {"std_msgs/msg/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n", {}},
      {"geometry_msgs/msg/Vector3", "float64 x\nfloat64 y\nfloat64 z\n", {}},
      {"geometry_msgs/msg/Point", "float64 x\nfloat64 y\nfloat64 z\n", {}},
      {"geometry_msgs/msg/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n", {}},
      {"geometry_msgs/msg/Pose",
       "Point position\nQuaternion orientation\n",
       {"geometry_msgs/msg/Point", "geometry_msgs/msg/Quaternion"}},
      {"geometry_msgs/msg/Transform",
       "Vector3 translation\nQuaternion rotation\n",
       {"geometry_msgs/msg/Vector3", "geometry_msgs/msg/Quaternion"}},
      {"geometry_msgs/msg/TransformStamped",
       "std_msgs/Header header\nstring child_frame_id\nTransform transform\n",
       {"std_msgs/msg/Header", "geometry_msgs/msg/Transform"}},
      {"tf2_msgs/msg/TFMessage",
       "geometry_msgs/TransformStamped[] transforms\n",
       {"geometry_msgs/msg/TransformStamped"}},
      {"trajectory_msgs/msg/JointTrajectoryPoint",
       "float64[] positions\nfloat64[] velocities\nfloat64[] accelerations\nfloat64[] effort\n"
       "builtin_interfaces/Duration time_from_start\n",
       {"builtin_interfaces/msg/Duration"}},
      {"trajectory_msgs/msg/JointTrajectory",
       "std_msgs/Header header\nstring[] joint_names\nJointTrajectoryPoint[] points\n",
       {"std_msgs/msg/Header", "trajectory_msgs/msg/JointTrajectoryPoint"}},
      {"sensor_msgs/msg/JointState",
       "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
       "float64[] effort\n",
       {"std_msgs/msg/Header"}},
      {"sensor_msgs/msg/PointField",
       "uint8 INT8=1\nuint8 UINT8=2\nuint8 INT16=3\nuint8 UINT16=4\nuint8 INT32=5\n"
       "uint8 UINT32=6\nuint8 FLOAT32=7\nuint8 FLOAT64=8\n"
       "string name\nuint32 offset\nuint8 datatype\nuint32 count\n",
       {}},
      {"sensor_msgs/msg/PointCloud2",
       "std_msgs/Header header\nuint32 height\nuint32 width\nPointField[] fields\n"
       "bool is_bigendian\nuint32 point_step\nuint32 row_step\nuint8[] data\nbool is_dense\n",
       {"std_msgs/msg/Header", "sensor_msgs/msg/PointField"}},
      {"sensor_msgs/msg/CompressedImage",
       "std_msgs/Header header\nstring format\nuint8[] data\n",
       {"std_msgs/msg/Header"}},
      {"visualization_msgs/msg/UVCoordinate", "float32 u\nfloat32 v\n", {}},
      {"visualization_msgs/msg/MeshFile", "string filename\nuint8[] data\n", {}},
      {"visualization_msgs/msg/Marker",
       "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\n"
       "int32 LINE_LIST=5\nint32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\n"
       "int32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\nint32 TRIANGLE_LIST=11\n"
       "int32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\nint32 DELETEALL=3\n"
       "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\n"
       "geometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\n"
       "builtin_interfaces/Duration lifetime\nbool frame_locked\n"
       "geometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\n"
       "string texture_resource\nsensor_msgs/CompressedImage texture\n"
       "UVCoordinate[] uv_coordinates\nstring text\nstring mesh_resource\n"
       "MeshFile mesh_file\nbool mesh_use_embedded_materials\n",
       {"std_msgs/msg/Header", "geometry_msgs/msg/Pose", "geometry_msgs/msg/Vector3",
        "std_msgs/msg/ColorRGBA", "builtin_interfaces/msg/Duration", "geometry_msgs/msg/Point",
        "sensor_msgs/msg/CompressedImage", "visualization_msgs/msg/UVCoordinate",
        "visualization_msgs/msg/MeshFile"}},
      {"visualization_msgs/msg/MarkerArray",
       "Marker[] markers\n",
       {"visualization_msgs/msg/Marker"}},
  };
  return table;
}

const MsgDefinition& msg_definition(std::string_view type) {
  for (const MsgDefinition& d : msg_definitions())
    if (d.type == type) return d;
  throw InputError("ROS 2 message type " + std::string(type) + ": not one rodshape writes");
}

/// The types `type` uses, each once, depth first in field order.
void msg_dependencies(std::string_view type,
                      std::vector<std::string_view>& order,
                      std::set<std::string_view>& seen) {
  for (std::string_view used : msg_definition(type).uses) {
    if (!seen.insert(used).second) continue;
    order.push_back(used);
    msg_dependencies(used, order, seen);
  }
}

void cdr_write(CdrWriter& out, const RosTime& time) {
  out.write_int32(time.sec);
  out.write_uint32(time.nanosec);
}

void cdr_write(CdrWriter& out, const RosHeader& header) {
  cdr_write(out, header.stamp);
  out.write_string(header.frame_id);
}

void cdr_write_strings(CdrWriter& out, const std::vector<std::string>& values) {
  out.write_length(values.size());
  for (const std::string& value : values) out.write_string(value);
}

void cdr_write_xyz(CdrWriter& out, const Eigen::Vector3d& v) {
  out.write_float64(v.x());
  out.write_float64(v.y());
  out.write_float64(v.z());
}

void cdr_write_xyzw(CdrWriter& out, const Eigen::Quaterniond& q) {
  out.write_float64(q.x());
  out.write_float64(q.y());
  out.write_float64(q.z());
  out.write_float64(q.w());
}

void cdr_write(CdrWriter& out, const RosColor& c) {
  out.write_float32(c.r);
  out.write_float32(c.g);
  out.write_float32(c.b);
  out.write_float32(c.a);
}

void cdr_write(CdrWriter& out, const RosMarker& m) {
  cdr_write(out, m.header);
  out.write_string(m.ns);
  out.write_int32(m.id);
  out.write_int32(m.type);
  out.write_int32(m.action);
  cdr_write_xyz(out, m.position);
  cdr_write_xyzw(out, m.orientation);
  cdr_write_xyz(out, m.scale);
  cdr_write(out, m.color);
  cdr_write(out, m.lifetime);
  out.write_bool(m.frame_locked);
  out.write_length(m.points.size());
  for (const Eigen::Vector3d& p : m.points) cdr_write_xyz(out, p);
  out.write_length(m.colors.size());
  for (const RosColor& c : m.colors) cdr_write(out, c);
  out.write_string("");         // texture_resource
  cdr_write(out, RosHeader{});  // texture: sensor_msgs/CompressedImage, empty
  out.write_string("");
  out.write_uint8_sequence("");
  out.write_length(0);  // uv_coordinates
  out.write_string(m.text);
  out.write_string("");  // mesh_resource
  out.write_string("");  // mesh_file: filename, data
  out.write_uint8_sequence("");
  out.write_bool(false);  // mesh_use_embedded_materials
}

}  // namespace

RosTime RosTime::from_seconds(double seconds) {
  const double ns = std::round(seconds * 1e9);
  if (!(ns >= 0.0) || ns >= 1e9 * static_cast<double>(std::numeric_limits<std::int32_t>::max()))
    throw InputError("ROS 2 time " + std::to_string(seconds) + " s: outside [0, 2^31) s");
  const auto total = static_cast<std::uint64_t>(ns);
  return {static_cast<std::int32_t>(total / 1000000000ULL),
          static_cast<std::uint32_t>(total % 1000000000ULL)};
}

RosPointCloud2 RosPointCloud2::xyz(RosHeader header, const std::vector<Eigen::Vector3d>& points) {
  RosPointCloud2 cloud;
  cloud.header = std::move(header);
  cloud.width = static_cast<std::uint32_t>(points.size());
  cloud.fields = {{"x", 0}, {"y", 4}, {"z", 8}};
  cloud.point_step = 12;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.resize(std::size_t{cloud.row_step});
  char* out = cloud.data.data();
  for (const Eigen::Vector3d& p : points)
    for (int k = 0; k < 3; ++k) {
      const auto value = static_cast<float>(p(k));
      std::memcpy(out, &value, 4);  // little endian (is_bigendian false), as the host's
      out += 4;
    }
  cloud.is_dense = true;
  return cloud;
}

std::string ros_cdr(const RosJointTrajectory& message) {
  CdrWriter out;
  cdr_write(out, message.header);
  cdr_write_strings(out, message.joint_names);
  out.write_length(message.points.size());
  for (const RosJointTrajectoryPoint& point : message.points) {
    out.write_float64_sequence(point.positions);
    out.write_float64_sequence(point.velocities);
    out.write_float64_sequence(point.accelerations);
    out.write_float64_sequence(point.effort);
    cdr_write(out, point.time_from_start);
  }
  return out.take();
}

std::string ros_cdr(const RosJointState& message) {
  CdrWriter out;
  cdr_write(out, message.header);
  cdr_write_strings(out, message.name);
  out.write_float64_sequence(message.position);
  out.write_float64_sequence(message.velocity);
  out.write_float64_sequence(message.effort);
  return out.take();
}

std::string ros_cdr(const RosTfMessage& message) {
  CdrWriter out;
  out.write_length(message.transforms.size());
  for (const RosTransformStamped& t : message.transforms) {
    cdr_write(out, t.header);
    out.write_string(t.child_frame_id);
    cdr_write_xyz(out, t.translation);
    cdr_write_xyzw(out, t.rotation);
  }
  return out.take();
}

std::string ros_cdr(const RosMarkerArray& message) {
  CdrWriter out;
  out.write_length(message.markers.size());
  for (const RosMarker& marker : message.markers) cdr_write(out, marker);
  return out.take();
}

std::string ros_cdr(const RosPointCloud2& message) {
  CdrWriter out;
  cdr_write(out, message.header);
  out.write_uint32(message.height);
  out.write_uint32(message.width);
  out.write_length(message.fields.size());
  for (const RosPointField& field : message.fields) {
    out.write_string(field.name);
    out.write_uint32(field.offset);
    out.write_uint8(field.datatype);
    out.write_uint32(field.count);
  }
  out.write_bool(message.is_bigendian);
  out.write_uint32(message.point_step);
  out.write_uint32(message.row_step);
  out.write_uint8_sequence(message.data);
  out.write_bool(message.is_dense);
  return out.take();
}

std::string ros_schema(std::string_view type) {
  std::string text(msg_definition(type).text);
  std::vector<std::string_view> order;
  std::set<std::string_view> seen{type};
  msg_dependencies(type, order, seen);
  for (std::string_view used : order) {
    // "MSG: std_msgs/Header": the name as the .msg texts' fields spell it (rosbag2's form), so
    // that a parser resolves each field's type to its heading.
    std::string name(used);
    name.erase(name.find("/msg/"), 4);
    text += std::string(80, '=') + "\nMSG: " + name + "\n";
    text += msg_definition(used).text;
  }
  return text;
}

}  // namespace rodshape
