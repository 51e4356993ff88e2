// SPDX-License-Identifier: GPL-3.0-or-later
// URDF skeleton reading (urdfdom) with file:line diagnostics, and posture motions.
// urdfdom reports problems through console_bridge without line numbers; the messages are
// captured and the line of the named link/joint is looked up in the file text.
#include "hbm/deckgen/skeleton.hpp"

#include "hbm/deckgen/table.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace hbm::deckgen {

namespace {

// Level name such as "C7" or "T12". Built by appending: GCC 12 reports a false -Wrestrict
// on "T" + std::to_string(i) (the prepend of the literal into the temporary).
std::string level_name(char region, int i) {
  std::string name(1, region);
  name += std::to_string(i);
  return name;
}

class CapturingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages.push_back(text);
  }
  std::vector<std::string> messages;
};

// 1-based line of the first occurrence of `needle` in `text` (0 if absent).
int line_of(const std::string& text, const std::string& needle, std::size_t from = 0) {
  std::size_t pos = text.find(needle, from);
  if (pos == std::string::npos) return 0;
  int line = 1;
  for (std::size_t i = 0; i < pos; ++i)
    if (text[i] == '\n') ++line;
  return line;
}

int element_line(const std::string& text, const std::string& tag, const std::string& name) {
  int l = line_of(text, "<" + tag + " name=\"" + name + "\"");
  return l ? l : line_of(text, "\"" + name + "\"");
}

Eigen::Isometry3d to_iso(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z) * 1000.0;
  t.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).toRotationMatrix();
  return t;
}

}  // namespace

const std::vector<std::string>& Skeleton::required_links() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v{"pelvis", "head"};
    for (int i = 1; i <= 7; ++i) v.push_back(level_name('C', i));
    for (int i = 1; i <= 12; ++i) v.push_back(level_name('T', i));
    for (int i = 1; i <= 5; ++i) v.push_back(level_name('L', i));
    for (const char* s : {"_r", "_l"})
      for (const char* b : {"clavicle", "scapula", "humerus", "forearm", "femur", "tibia"})
        v.push_back(std::string(b) + s);
    return v;
  }();
  return names;
}

const std::vector<std::string>& Skeleton::rigid_links() {
  static const std::vector<std::string> names{"head", "humerus_r", "humerus_l", "forearm_r", "forearm_l",
                                              "femur_r", "femur_l", "tibia_r", "tibia_l"};
  return names;
}

Skeleton Skeleton::read(const std::filesystem::path& urdf_path) {
  std::ifstream in(urdf_path, std::ios::binary);
  if (!in) throw SourceError(urdf_path, 0, "", "cannot open URDF file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();

  CapturingHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  console_bridge::restorePreviousOutputHandler();
  if (!model) {
    std::string msg = handler.messages.empty() ? std::string("invalid URDF") : handler.messages.back();
    // Point at the element the message names, if any.
    int line = 0;
    for (const std::string& m : handler.messages) {
      std::size_t q = m.find('[');
      if (q != std::string::npos) {
        std::size_t e = m.find(']', q);
        if (e != std::string::npos) {
          std::string quoted(1, '"');  // appended in steps (GCC 12 false -Wrestrict on "\"" + ...)
          quoted += m.substr(q + 1, e - q - 1);
          quoted += '"';
          line = line_of(text, quoted);
        }
      }
    }
    throw SourceError(urdf_path, line, "urdf", msg);
  }

  Skeleton sk;
  sk.path_ = urdf_path;
  auto root = model->getRoot();
  if (!root) throw SourceError(urdf_path, 1, "urdf", "no root link");

  // Depth-first from the root, in the order children appear (deterministic).
  std::function<void(const urdf::LinkConstSharedPtr&, int, const Eigen::Isometry3d&)> visit;
  visit = [&](const urdf::LinkConstSharedPtr& l, int parent, const Eigen::Isometry3d& parent_frame) {
    SkeletonLink s;
    s.name = l->name;
    s.parent = parent;
    s.line = element_line(text, "link", l->name);
    Eigen::Isometry3d frame = parent_frame;
    if (auto j = l->parent_joint) {
      s.joint = j->name;
      s.joint_line = element_line(text, "joint", j->name);
      frame = parent_frame * to_iso(j->parent_to_joint_origin_transform);
      s.joint_origin = frame.translation();
      Eigen::Vector3d ax(j->axis.x, j->axis.y, j->axis.z);
      if (j->type == urdf::Joint::REVOLUTE || j->type == urdf::Joint::CONTINUOUS) {
        if (ax.norm() < 1e-9) throw SourceError(urdf_path, s.joint_line, "axis", "joint " + j->name + " has a zero axis");
        s.axis = frame.linear() * ax.normalized();
      }
      if (j->type == urdf::Joint::REVOLUTE) {
        if (!j->limits) throw SourceError(urdf_path, s.joint_line, "limit", "revolute joint " + j->name + " without limits");
        s.lower = j->limits->lower;
        s.upper = j->limits->upper;
        if (!(s.lower <= 0 && s.upper >= 0 && s.lower < s.upper))
          throw SourceError(urdf_path, s.joint_line, "limit",
                            "joint " + j->name + ": limits must bracket the seated posture (lower <= 0 <= upper)");
      } else if (j->type == urdf::Joint::FIXED) {
        s.lower = s.upper = 0;
      } else {
        throw SourceError(urdf_path, s.joint_line, "type", "joint " + j->name + ": only revolute and fixed joints are supported");
      }
    }
    if (auto inertial = l->inertial) {
      s.has_inertial = true;
      s.mass = inertial->mass;
      Eigen::Isometry3d io = frame * to_iso(inertial->origin);
      s.cog = io.translation();
      Eigen::Matrix3d I;
      I << inertial->ixx, inertial->ixy, inertial->ixz,  //
          inertial->ixy, inertial->iyy, inertial->iyz,     //
          inertial->ixz, inertial->iyz, inertial->izz;
      s.inertia = io.linear() * (I * 1e6) * io.linear().transpose();
      int il = line_of(text, "<inertial>", text.find("<link name=\"" + l->name + "\""));
      if (!(s.mass > 0)) throw SourceError(urdf_path, il ? il : s.line, "mass", "link " + l->name + ": mass must be > 0");
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(s.inertia);
      if (es.eigenvalues().minCoeff() <= 0)
        throw SourceError(urdf_path, il ? il : s.line, "inertia", "link " + l->name + ": inertia is not positive definite");
      Eigen::Vector3d ev = es.eigenvalues();
      if (ev(0) + ev(1) < ev(2) * (1 - 1e-9) || ev(0) + ev(2) < ev(1) * (1 - 1e-9))
        throw SourceError(urdf_path, il ? il : s.line, "inertia", "link " + l->name + ": principal moments violate the triangle inequality");
    }
    int me = static_cast<int>(sk.links_.size());
    sk.links_.push_back(s);
    for (const auto& c : l->child_links) visit(c, me, frame);
  };
  visit(root, -1, Eigen::Isometry3d::Identity());

  for (const std::string& n : required_links())
    if (sk.index(n) < 0) throw SourceError(urdf_path, 1, "link", "required link '" + n + "' is missing");
  for (const std::string& n : rigid_links())
    if (!sk.link(n).has_inertial)
      throw SourceError(urdf_path, sk.link(n).line, "inertial", "rigid segment '" + n + "' needs mass, origin and inertia");
  return sk;
}

int Skeleton::index(const std::string& name) const {
  for (std::size_t i = 0; i < links_.size(); ++i)
    if (links_[i].name == name) return static_cast<int>(i);
  return -1;
}

const SkeletonLink& Skeleton::link(const std::string& name) const {
  int i = index(name);
  if (i < 0) throw std::out_of_range("skeleton has no link " + name);
  return links_[static_cast<std::size_t>(i)];
}

void Skeleton::set_joint(const std::string& joint, double angle) {
  for (const auto& l : links_)
    if (l.joint == joint) {
      if (angle < l.lower - 1e-12 || angle > l.upper + 1e-12) {
        std::ostringstream m;
        m << "joint " << joint << ": angle " << angle * 180 / M_PI << " deg outside its limits ["
          << l.lower * 180 / M_PI << ", " << l.upper * 180 / M_PI << "] deg (" << path_.string() << ":" << l.joint_line << ")";
        throw std::invalid_argument(m.str());
      }
      angles_[joint] = angle;
      return;
    }
  throw std::invalid_argument("no joint named '" + joint + "' in " + path_.string());
}

double Skeleton::joint_angle(const std::string& joint) const {
  auto it = angles_.find(joint);
  return it == angles_.end() ? 0.0 : it->second;
}

Eigen::Isometry3d Skeleton::motion(const std::string& name) const {
  // Compose parent motions: a joint rotation acts about the joint origin as moved by the
  // ancestors.
  int i = index(name);
  if (i < 0) throw std::out_of_range("skeleton has no link " + name);
  std::vector<int> chain;
  for (int k = i; k >= 0; k = links_[static_cast<std::size_t>(k)].parent) chain.push_back(k);
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const SkeletonLink& l = links_[static_cast<std::size_t>(*it)];
    double a = joint_angle(l.joint);
    if (l.joint.empty() || a == 0.0) continue;
    Eigen::Isometry3d r = Eigen::Isometry3d::Identity();
    r.translate(l.joint_origin);
    r.rotate(Eigen::AngleAxisd(a, l.axis));
    r.translate(-l.joint_origin);
    m = m * r;
  }
  return m;
}

bool Skeleton::descends_from(const std::string& name, const std::string& ancestor) const {
  for (int k = index(name); k >= 0; k = links_[static_cast<std::size_t>(k)].parent)
    if (links_[static_cast<std::size_t>(k)].name == ancestor) return true;
  return false;
}

}  // namespace hbm::deckgen
