// arm_model.cpp: URDF (urdfdom) -> KDL::Chain between two links, with the joint limits.
//
// Each URDF joint becomes one KDL segment named after its child link, as kdl_parser builds them:
// the segment's frame at q is F_parent_joint · Rot(axis, q) (or · Trans(axis · q)), with
// F_parent_joint the joint's <origin>. Fixed joints are segments with a KDL::Joint::Fixed joint.
#include "rodshape/robot/arm_model.hpp"

#include <console_bridge/console.h>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/frames.hpp>
#include <kdl/jacobian.hpp>
#include <kdl/jntarray.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "capped_file.hpp"
#include "robot/urdf_extent.hpp"
#include "rodshape/core/segment.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

struct ArmModel::Impl {
  std::string robot_name;
  std::string base_link;
  std::string tip_link;
  // The chain as read, never evaluated: KDL's Joint::pose() and Segment::pose() cache the last pose
  // in mutable members, so evaluating one chain from two threads is a data race (copies of an
  // ArmModel share this Impl). Every evaluation works on its own copy (evaluable_chain()); copying
  // only reads these members, which nothing ever writes here.
  KDL::Chain chain;
  // This Impl's number, never reused in the process: the key of each thread's copies of the chain
  // and its solvers (evaluator()).
  std::uint64_t id = 0;
  std::vector<JointInfo> joints;
  double reach = 0.0;
  std::vector<LinkCapsule> capsules;
  std::vector<std::string> collision_notes;
  std::vector<std::string> frame_links;  // the base link, then each segment's child link
  std::vector<int> frame_joints;         // moving joints that move each frame
};

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The cap on a URDF file's size (docs/limits.md); robot descriptions are tens to hundreds of KB.
constexpr detail::FileCap kUrdfFileCap{4 * detail::kMiB, "a URDF file",
                                       "cannot read the URDF file"};

std::string in_quotes(const std::string& name) { return "'" + name + "'"; }

/// Collects what urdfdom reports through console_bridge while it parses (instead of printing it),
/// so that the InputError can say why the URDF did not parse.
class CapturingHandler final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text,
           console_bridge::LogLevel level,
           const char* /*filename*/,
           int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      if (!errors.empty()) errors += "; ";
      errors += text;
    }
  }
  std::string errors;
};

/// urdfdom's reason in words: its XML parser's messages ("Error document empty.") are said as what
/// they mean for the file.
std::string urdf_error(const std::string& urdf, const std::string& errors) {
  if (urdf.find_first_not_of(" \t\r\n") == std::string::npos) return "the file is empty";
  if (errors.empty()) return "not a valid URDF robot";
  if (errors.starts_with("Error document empty"))
    return "it is not XML (no XML element found; a URDF is an XML file with a <robot> element)";
  if (errors.starts_with("Could not find the 'robot' element"))
    return "no <robot> element (a URDF is an XML file with a <robot> element)";
  if (errors.starts_with("Error ")) {
    // TinyXML: "Error reading end tag." and the like.
    std::string what = errors.substr(6);
    if (const std::size_t end = what.find('.'); end != std::string::npos) what.resize(end);
    return "malformed XML (error " + what + ")";
  }
  if (errors.find("No root link") != std::string::npos)
    return errors + " (the joints form a closed loop)";
  return errors;
}

urdf::ModelInterfaceSharedPtr parse_urdf(const std::string& urdf, const std::string& source) {
  // console_bridge's handler is process-wide; parse one URDF at a time.
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  CapturingHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(urdf);
  } catch (const std::exception& error) {
    handler.errors += (handler.errors.empty() ? "" : "; ") + std::string(error.what());
  }
  console_bridge::restorePreviousOutputHandler();
  if (!model)
    throw InputError(source + ": the URDF does not parse: " + urdf_error(urdf, handler.errors));
  return model;
}

KDL::Vector to_kdl(const urdf::Vector3& v) { return KDL::Vector(v.x, v.y, v.z); }

KDL::Frame to_kdl(const urdf::Pose& pose) {
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
  pose.rotation.getQuaternion(x, y, z, w);
  return KDL::Frame(KDL::Rotation::Quaternion(x, y, z, w), to_kdl(pose.position));
}

std::vector<std::string> link_names(const urdf::ModelInterface& model) {
  std::vector<std::string> names;
  for (const auto& [name, link] : model.links_) names.push_back(name);
  return names;
}

urdf::LinkConstSharedPtr find_link(const urdf::ModelInterface& model,
                                   const std::string& name,
                                   const std::string& role,
                                   const std::string& source) {
  urdf::LinkConstSharedPtr link = model.getLink(name);
  if (link) return link;
  std::string known;
  for (const std::string& candidate : link_names(model))
    known += (known.empty() ? "" : ", ") + candidate;
  throw InputError(source + ": unknown " + role + " link " + in_quotes(name) + " in robot " +
                   in_quotes(model.getName()) + " (links: " + known + ")");
}

/// A link that is the child of two joints closes a loop; urdfdom keeps only one of the two.
void reject_closed_loops(const urdf::ModelInterface& model, const std::string& source) {
  std::map<std::string, std::string> parent_joint_of;
  for (const auto& [name, joint] : model.joints_) {
    const auto [it, inserted] = parent_joint_of.emplace(joint->child_link_name, name);
    if (!inserted) {
      throw InputError(source + ": the joints form a closed loop: link " +
                       in_quotes(joint->child_link_name) + " is the child of both " +
                       in_quotes(it->second) + " and " + in_quotes(name) +
                       "; a serial chain needs a tree");
    }
  }
}

/// The deepest leaf below `base`; throws when two leaves are equally deep (the tip is ambiguous).
std::string default_tip(const urdf::LinkConstSharedPtr& base, const std::string& source) {
  std::vector<std::string> deepest;
  int deepest_depth = -1;
  std::vector<std::pair<urdf::LinkConstSharedPtr, int>> stack{{base, 0}};
  while (!stack.empty()) {
    const auto [link, depth] = stack.back();
    stack.pop_back();
    if (link->child_links.empty()) {
      if (depth > deepest_depth) {
        deepest_depth = depth;
        deepest.clear();
      }
      if (depth == deepest_depth) deepest.push_back(link->name);
    }
    for (const auto& child : link->child_links) stack.emplace_back(child, depth + 1);
  }
  if (deepest.size() > 1) {
    std::sort(deepest.begin(), deepest.end());
    std::string names;
    for (const std::string& name : deepest) names += (names.empty() ? "" : ", ") + name;
    throw InputError(source + ": the chain below " + in_quotes(base->name) +
                     " branches into equally long chains ending at " + names +
                     "; name the tip link (--tip)");
  }
  return deepest.front();
}

JointInfo read_joint_info(const urdf::Joint& joint, const std::string& source) {
  const std::string where = source + ": joint " + in_quotes(joint.name);
  JointInfo info;
  info.name = joint.name;
  info.prismatic = joint.type == urdf::Joint::PRISMATIC;
  if (joint.type == urdf::Joint::CONTINUOUS) {
    info.lower = -kInfinity;
    info.upper = kInfinity;
    info.max_velocity =
        joint.limits && joint.limits->velocity > 0.0 ? joint.limits->velocity : kInfinity;
    return info;
  }
  if (!joint.limits) throw InputError(where + " has no <limit>");
  info.lower = joint.limits->lower;
  info.upper = joint.limits->upper;
  info.max_velocity = joint.limits->velocity;
  if (!std::isfinite(info.lower) || !std::isfinite(info.upper) || !(info.lower <= info.upper)) {
    throw InputError(where + ": limit lower = " + detail::format_value(info.lower) +
                     " and upper = " + detail::format_value(info.upper) +
                     " must be finite with lower <= upper");
  }
  if (!(info.max_velocity > 0.0)) {
    throw InputError(where + ": limit velocity = " + detail::format_value(info.max_velocity) +
                     " must be > 0");
  }
  return info;
}

/// The KDL segment of one URDF joint (named after its child link), and whether it moves.
KDL::Segment segment_of(const urdf::Joint& joint, const std::string& source) {
  const std::string where = source + ": joint " + in_quotes(joint.name);
  const KDL::Frame parent_T_joint = to_kdl(joint.parent_to_joint_origin_transform);
  switch (joint.type) {
    case urdf::Joint::FIXED:
      return KDL::Segment(joint.child_link_name, KDL::Joint(joint.name, KDL::Joint::Fixed),
                          parent_T_joint);
    case urdf::Joint::REVOLUTE:
    case urdf::Joint::CONTINUOUS:
    case urdf::Joint::PRISMATIC: {
      if (joint.mimic)
        throw InputError(where + " mimics another joint; mimic joints are not supported");
      KDL::Vector axis = to_kdl(joint.axis);
      const double norm = axis.Norm();
      if (!(norm > 1e-12) || !std::isfinite(norm))
        throw InputError(where + " has a zero or non-finite <axis>");
      axis = axis / norm;
      const KDL::Joint::JointType type =
          joint.type == urdf::Joint::PRISMATIC ? KDL::Joint::TransAxis : KDL::Joint::RotAxis;
      return KDL::Segment(joint.child_link_name,
                          KDL::Joint(joint.name, parent_T_joint.p, parent_T_joint.M * axis, type),
                          parent_T_joint);
    }
    case urdf::Joint::FLOATING:
      throw InputError(where +
                       " is floating; a serial chain needs revolute, continuous, "
                       "prismatic or fixed joints");
    case urdf::Joint::PLANAR:
      throw InputError(where +
                       " is planar; a serial chain needs revolute, continuous, "
                       "prismatic or fixed joints");
    default:
      throw InputError(where + " has an unknown type");
  }
}

Pose to_pose(const KDL::Frame& frame) {
  Pose pose;
  pose.position = Eigen::Vector3d(frame.p.x(), frame.p.y(), frame.p.z());
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) pose.rotation(r, c) = frame.M(r, c);
  return pose;
}

/// Numbers for ArmModel::Impl::id.
std::atomic<std::uint64_t> next_impl_id{1};

/// A thread's own copy of a chain (see ArmModel::Impl::chain) with its solvers, made once per
/// thread and model instead of at every evaluation: the same KDL computations on an equal chain,
/// so the same values (KDL's cached joint pose is recomputed whenever q changes).
struct Evaluator {
  std::uint64_t id;
  KDL::Chain chain;  // before the solvers, which keep a reference to it
  KDL::ChainFkSolverPos_recursive fk;
  KDL::ChainJntToJacSolver jacobian;
  KDL::JntArray q;
  Evaluator(std::uint64_t impl_id, const KDL::Chain& prototype)
      : id(impl_id), chain(prototype), fk(chain), jacobian(chain), q(chain.getNrOfJoints()) {}
};

/// The calling thread's evaluator of `prototype` (Impl `id`): the few most recently used are
/// kept per thread.
Evaluator& evaluator(std::uint64_t id, const KDL::Chain& prototype) {
  constexpr std::size_t kKept = 4;
  thread_local std::vector<std::unique_ptr<Evaluator>> kept;  // most recently used first
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (kept[i]->id != id) continue;
    if (i > 0)
      std::rotate(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(i),
                  kept.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    return *kept.front();
  }
  if (kept.size() == kKept) kept.pop_back();
  kept.insert(kept.begin(), std::make_unique<Evaluator>(id, prototype));
  return *kept.front();
}

Eigen::Vector3d to_eigen(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

Eigen::Matrix3d to_eigen(const urdf::Rotation& r) {
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
  r.getQuaternion(x, y, z, w);
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

/// The capsule that covers one <collision> primitive (link_capsule.hpp), in the link's frame;
/// nullopt for a mesh (a note says so).
std::optional<LinkCapsule> capsule_of(const urdf::Collision& collision,
                                      const std::string& link,
                                      int frame,
                                      const std::string& source,
                                      std::vector<std::string>& notes) {
  const std::string where = source + ": link " + in_quotes(link) + ": <collision>";
  if (!collision.geometry) return std::nullopt;
  const Eigen::Vector3d origin = to_eigen(collision.origin.position);
  const Eigen::Matrix3d rotation = to_eigen(collision.origin.rotation);
  LinkCapsule capsule;
  capsule.link = link;
  capsule.name = collision.name;
  capsule.frame = frame;
  Eigen::Vector3d half_axis = Eigen::Vector3d::Zero();  // in the collision's own frame
  const urdf::Geometry& geometry = *collision.geometry;
  switch (geometry.type) {
    case urdf::Geometry::SPHERE:
      capsule.radius = static_cast<const urdf::Sphere&>(geometry).radius;
      break;
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      capsule.radius = cylinder.radius;
      half_axis = Eigen::Vector3d(0.0, 0.0, 0.5 * cylinder.length);
      if (!std::isfinite(cylinder.length) || cylinder.length < 0.0)
        throw InputError(where + " cylinder length = " + detail::format_value(cylinder.length) +
                         " must be finite and >= 0");
      break;
    }
    case urdf::Geometry::BOX: {
      const Eigen::Vector3d size = to_eigen(static_cast<const urdf::Box&>(geometry).dim);
      if (!size.allFinite() || (size.array() < 0.0).any())
        throw InputError(where + " box size must be finite and >= 0");
      Eigen::Index longest = 0;
      size.maxCoeff(&longest);
      half_axis(longest) = 0.5 * size(longest);
      capsule.radius = 0.5 * std::sqrt(size.squaredNorm() - size(longest) * size(longest));
      break;
    }
    case urdf::Geometry::MESH:
      notes.push_back("link " + in_quotes(link) + ": a <mesh> collision" +
                      (collision.name.empty() ? "" : " " + in_quotes(collision.name)) +
                      " is ignored (meshes are not read; give spheres, cylinders or boxes)");
      return std::nullopt;
    default:
      return std::nullopt;
  }
  if (!std::isfinite(capsule.radius) || capsule.radius < 0.0)
    throw InputError(where + " radius = " + detail::format_value(capsule.radius) +
                     " must be finite and >= 0");
  capsule.from = origin - rotation * half_axis;
  capsule.to = origin + rotation * half_axis;
  if (!capsule.from.allFinite() || !capsule.to.allFinite())
    throw InputError(where + " <origin> is not finite");
  return capsule;
}

/// Whether the ball (c, r) lies within the capsule.
bool ball_within(const Eigen::Vector3d& c, double r, const LinkCapsule& capsule) {
  const Eigen::Vector3d ab = capsule.to - capsule.from;
  const double t = nearest_on_segment(c, capsule.from, capsule.to);
  return (c - capsule.from - t * ab).norm() + r <= capsule.radius + 1e-9;
}

/// The capsules of one link (frame `frame`), spheres inside another of its capsules dropped.
void read_link_capsules(const urdf::Link& link,
                        int frame,
                        const std::string& source,
                        std::vector<LinkCapsule>& capsules,
                        std::vector<std::string>& notes) {
  std::vector<LinkCapsule> own;
  for (const urdf::CollisionSharedPtr& collision : link.collision_array) {
    if (!collision) continue;
    std::optional<LinkCapsule> capsule = capsule_of(*collision, link.name, frame, source, notes);
    if (capsule) own.push_back(std::move(*capsule));
  }
  for (std::size_t i = 0; i < own.size(); ++i) {
    const bool ball = own[i].from == own[i].to;
    bool covered = false;
    for (std::size_t j = 0; j < own.size() && ball && !covered; ++j) {
      const bool other_ball = own[j].from == own[j].to;
      // a ball inside another ball: drop the smaller (the first of two equal ones survives)
      if (j != i && (!other_ball || own[j].radius > own[i].radius ||
                     (own[j].radius == own[i].radius && j < i)))
        covered = ball_within(own[i].from, own[i].radius, own[j]);
    }
    if (!covered) capsules.push_back(own[i]);
  }
  if (capsules.size() > static_cast<std::size_t>(ArmModel::kMaxLinkCapsules))
    throw InputError(source + ": more than " + std::to_string(ArmModel::kMaxLinkCapsules) +
                     " collision primitives on the chain's links");
}

}  // namespace

ArmModel ArmModel::from_urdf_file(const std::string& path,
                                  const std::string& base_link,
                                  const std::string& tip_link) {
  return from_urdf_string(detail::read_capped_file(path, kUrdfFileCap), base_link, tip_link, path);
}

ArmModel ArmModel::from_urdf_string(const std::string& urdf,
                                    const std::string& base_link,
                                    const std::string& tip_link,
                                    const std::string& source) {
  robot_detail::check_urdf_extent(urdf, source);
  const urdf::ModelInterfaceSharedPtr model = parse_urdf(urdf, source);
  reject_closed_loops(*model, source);

  const urdf::LinkConstSharedPtr base =
      base_link.empty() ? model->getRoot() : find_link(*model, base_link, "base", source);
  const std::string tip_name = tip_link.empty() ? default_tip(base, source) : tip_link;
  const urdf::LinkConstSharedPtr tip = find_link(*model, tip_name, "tip", source);

  // Walk up from the tip to the base, collecting the joints on the way.
  std::vector<urdf::JointConstSharedPtr> path;
  std::set<std::string> visited;
  for (urdf::LinkConstSharedPtr link = tip; link->name != base->name; link = link->getParent()) {
    if (!visited.insert(link->name).second || !link->parent_joint || !link->getParent()) {
      throw InputError(source + ": tip link " + in_quotes(tip->name) + " is not below base link " +
                       in_quotes(base->name) + " in robot " + in_quotes(model->getName()));
    }
    path.push_back(link->parent_joint);
  }
  std::reverse(path.begin(), path.end());

  auto impl = std::make_shared<Impl>();
  impl->id = next_impl_id.fetch_add(1, std::memory_order_relaxed);
  impl->robot_name = model->getName();
  impl->base_link = base->name;
  impl->tip_link = tip->name;
  impl->frame_links.push_back(base->name);
  impl->frame_joints.push_back(0);
  read_link_capsules(*base, 0, source, impl->capsules, impl->collision_notes);
  for (const urdf::JointConstSharedPtr& joint : path) {
    const KDL::Segment segment = segment_of(*joint, source);
    impl->reach += segment.getFrameToTip().p.Norm();
    if (segment.getJoint().getType() != KDL::Joint::Fixed) {
      impl->joints.push_back(read_joint_info(*joint, source));
      const JointInfo& info = impl->joints.back();
      if (info.prismatic) impl->reach += std::max(std::abs(info.lower), std::abs(info.upper));
    }
    impl->chain.addSegment(segment);
    impl->frame_links.push_back(joint->child_link_name);
    impl->frame_joints.push_back(static_cast<int>(impl->joints.size()));
    read_link_capsules(*model->getLink(joint->child_link_name),
                       static_cast<int>(impl->frame_links.size()) - 1, source, impl->capsules,
                       impl->collision_notes);
  }
  if (impl->joints.empty()) {
    throw InputError(source + ": the chain from " + in_quotes(base->name) + " to " +
                     in_quotes(tip->name) + " has no moving joint");
  }
  return ArmModel(std::move(impl));
}

ArmModel::ArmModel(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
ArmModel::ArmModel(const ArmModel&) = default;
ArmModel::ArmModel(ArmModel&&) noexcept = default;
ArmModel& ArmModel::operator=(const ArmModel&) = default;
ArmModel& ArmModel::operator=(ArmModel&&) noexcept = default;
ArmModel::~ArmModel() = default;

const std::string& ArmModel::robot_name() const { return impl_->robot_name; }
const std::string& ArmModel::base_link() const { return impl_->base_link; }
const std::string& ArmModel::tip_link() const { return impl_->tip_link; }
int ArmModel::joints() const { return static_cast<int>(impl_->joints.size()); }
const std::vector<JointInfo>& ArmModel::joint_info() const { return impl_->joints; }
double ArmModel::reach() const { return impl_->reach; }
const std::vector<LinkCapsule>& ArmModel::link_capsules() const { return impl_->capsules; }
const std::vector<std::string>& ArmModel::collision_notes() const { return impl_->collision_notes; }
const std::vector<std::string>& ArmModel::frame_links() const { return impl_->frame_links; }
int ArmModel::joints_moving_frame(int f) const {
  return impl_->frame_joints.at(static_cast<std::size_t>(f));
}

std::vector<std::string> ArmModel::joint_names() const {
  std::vector<std::string> names;
  for (const JointInfo& joint : impl_->joints) names.push_back(joint.name);
  return names;
}

Eigen::VectorXd ArmModel::lower_limits() const {
  Eigen::VectorXd values(joints());
  for (int i = 0; i < joints(); ++i) values(i) = impl_->joints[i].lower;
  return values;
}

Eigen::VectorXd ArmModel::upper_limits() const {
  Eigen::VectorXd values(joints());
  for (int i = 0; i < joints(); ++i) values(i) = impl_->joints[i].upper;
  return values;
}

Eigen::VectorXd ArmModel::velocity_limits() const {
  Eigen::VectorXd values(joints());
  for (int i = 0; i < joints(); ++i) values(i) = impl_->joints[i].max_velocity;
  return values;
}

Eigen::VectorXd ArmModel::acceleration_limits() const {
  Eigen::VectorXd values(joints());
  for (int i = 0; i < joints(); ++i) values(i) = impl_->joints[i].max_acceleration;
  return values;
}

Eigen::VectorXd ArmModel::jerk_limits() const {
  Eigen::VectorXd values(joints());
  for (int i = 0; i < joints(); ++i) values(i) = impl_->joints[i].max_jerk;
  return values;
}

ArmModel ArmModel::with_motion_limits(const Eigen::VectorXd& max_acceleration,
                                      const Eigen::VectorXd& max_jerk,
                                      const std::string& source) const {
  for (const auto& [values, what] :
       {std::pair{&max_acceleration, "acceleration"}, std::pair{&max_jerk, "jerk"}}) {
    if (values->size() != joints())
      throw InputError(source + ": " + std::to_string(values->size()) + " " + what +
                       " limits for the " + std::to_string(joints()) + " joints of " +
                       in_quotes(robot_name()));
    for (int i = 0; i < joints(); ++i)
      if (!((*values)(i) > 0.0))  // NaN too
        throw InputError(source + ": joint " + in_quotes(impl_->joints[i].name) + ": " + what +
                         " limit = " + detail::format_value((*values)(i)) + " must be > 0");
  }
  auto impl = std::make_shared<Impl>(*impl_);
  impl->id = next_impl_id.fetch_add(1, std::memory_order_relaxed);
  for (int i = 0; i < joints(); ++i) {
    impl->joints[i].max_acceleration = max_acceleration(i);
    impl->joints[i].max_jerk = max_jerk(i);
  }
  return ArmModel(std::move(impl));
}

void ArmModel::check_size(const Eigen::VectorXd& q, const std::string& what) const {
  if (q.size() != joints()) {
    throw InputError(what + " has " + std::to_string(q.size()) + " values but the chain from " +
                     in_quotes(base_link()) + " to " + in_quotes(tip_link()) + " has " +
                     std::to_string(joints()) + " joints");
  }
  detail::require_finite(what, q);
}

void ArmModel::check_joint_positions(const Eigen::VectorXd& q,
                                     const std::string& what,
                                     double tolerance) const {
  check_size(q, what);
  for (int i = 0; i < joints(); ++i) {
    const JointInfo& joint = impl_->joints[i];
    if (q(i) < joint.lower - tolerance || q(i) > joint.upper + tolerance) {
      throw InputError(what + "[" + std::to_string(i) + "] = " + detail::format_value(q(i)) +
                       " is outside the limits of joint " + in_quotes(joint.name) + ": [" +
                       detail::format_value(joint.lower) + ", " +
                       detail::format_value(joint.upper) + "]");
    }
  }
}

Eigen::VectorXd ArmModel::clamp_to_limits(const Eigen::VectorXd& q) const {
  assert(q.size() == joints());
  return q.cwiseMax(lower_limits()).cwiseMin(upper_limits());
}

Pose ArmModel::forward_kinematics(const Eigen::VectorXd& q) const {
  check_size(q, "q");
  Evaluator& evaluate = evaluator(impl_->id, impl_->chain);
  evaluate.q.data = q;
  KDL::Frame base_T_tip;
  const int code = evaluate.fk.JntToCart(evaluate.q, base_T_tip);
  if (code < 0) throw RodshapeError("KDL forward kinematics failed: " + std::to_string(code));
  return to_pose(base_T_tip);
}

void ArmModel::forward_kinematics(const Eigen::VectorXd& q,
                                  Pose& base_T_tip,
                                  Eigen::Matrix<double, 6, Eigen::Dynamic>& J_twist_q) const {
  base_T_tip = forward_kinematics(q);
  Evaluator& evaluate = evaluator(impl_->id, impl_->chain);
  KDL::Jacobian jacobian(static_cast<unsigned>(joints()));
  evaluate.q.data = q;
  const int code = evaluate.jacobian.JntToJac(evaluate.q, jacobian);
  if (code < 0) throw RodshapeError("KDL Jacobian failed: " + std::to_string(code));
  // KDL's Jacobian: rows vx vy vz ωx ωy ωz, base frame, reference point the chain's tip.
  J_twist_q = jacobian.data;
}

std::vector<JointAxis> ArmModel::joint_axes(const Eigen::VectorXd& q) const {
  LinkFrames frames;
  link_frames(q, frames);
  return std::move(frames.axes);
}

void ArmModel::link_frames(const Eigen::VectorXd& q, LinkFrames& out) const {
  check_size(q, "q");
  const KDL::Chain& chain = evaluator(impl_->id, impl_->chain).chain;
  const unsigned segments = chain.getNrOfSegments();
  out.frames.resize(segments + 1);
  out.axes.resize(impl_->joints.size());
  out.frames[0] = Pose{};
  KDL::Frame base_T_parent = KDL::Frame::Identity();
  int j = 0;
  for (unsigned i = 0; i < segments; ++i) {
    const KDL::Segment& segment = chain.getSegment(i);
    const KDL::Joint& joint = segment.getJoint();
    double q_segment = 0.0;
    if (joint.getType() != KDL::Joint::Fixed) {
      const KDL::Vector origin = base_T_parent * joint.JointOrigin();
      const KDL::Vector direction = base_T_parent.M * joint.JointAxis();
      JointAxis& axis = out.axes[static_cast<std::size_t>(j)];
      axis.origin = Eigen::Vector3d(origin.x(), origin.y(), origin.z());
      axis.direction = Eigen::Vector3d(direction.x(), direction.y(), direction.z()).normalized();
      q_segment = q(j++);
    }
    base_T_parent = base_T_parent * segment.pose(q_segment);
    out.frames[i + 1] = to_pose(base_T_parent);
  }
}

void ArmModel::point_jacobian(const LinkFrames& frames,
                              int f,
                              const Eigen::Vector3d& p,
                              Eigen::Matrix<double, 3, Eigen::Dynamic>& J) const {
  const int n = joints();
  J.resize(3, n);
  J.setZero();
  const int moving = joints_moving_frame(f);
  for (int j = 0; j < moving; ++j) {
    const JointAxis& axis = frames.axes[static_cast<std::size_t>(j)];
    if (impl_->joints[static_cast<std::size_t>(j)].prismatic)
      J.col(j) = axis.direction;
    else
      J.col(j) = axis.direction.cross(p - axis.origin);
  }
}

}  // namespace rodshape
