// SPDX-License-Identifier: GPL-3.0-or-later
// The skeleton read from geometry/skeleton.urdf (urdfdom): links with their joint to the
// parent (origin, axis, limits) and, for rigid segments, mass, centre of gravity and
// inertia. Lengths are converted from URDF metres to mm, inertia to kg*mm^2. A posture is
// a set of joint angles relative to the seated posture; `motion(link)` is the rigid
// motion that carries a point attached to the link from the seated posture to the posture.
#pragma once

#include <Eigen/Geometry>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hbm::deckgen {

struct SkeletonLink {
  std::string name;
  int parent = -1;              // index into Skeleton::links, -1 for the root
  std::string joint;            // joint to the parent ("" for the root)
  Eigen::Vector3d joint_origin = Eigen::Vector3d::Zero();  // model frame, seated posture, mm
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();         // model frame, unit
  double lower = 0, upper = 0;  // joint limits, rad, relative to the seated posture
  bool has_inertial = false;
  double mass = 0;                                          // kg
  Eigen::Vector3d cog = Eigen::Vector3d::Zero();            // model frame, mm
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();        // about cog, model axes, kg*mm^2
  int line = 0;                 // line of the <link> in the URDF, for messages
  int joint_line = 0;
};

class Skeleton {
 public:
  // Reads and checks the URDF: the links listed in required_links() must exist, rigid
  // segments need a positive mass and a positive-definite inertia, joint limits must
  // bracket 0. Throws SourceError (file:line) on any problem.
  static Skeleton read(const std::filesystem::path& urdf);
  static const std::vector<std::string>& required_links();
  static const std::vector<std::string>& rigid_links();

  const std::vector<SkeletonLink>& links() const { return links_; }
  const SkeletonLink& link(const std::string& name) const;
  int index(const std::string& name) const;  // -1 if absent
  const std::filesystem::path& path() const { return path_; }

  // Sets a joint angle (rad, relative to seated). Throws std::invalid_argument if the
  // joint does not exist or the angle is outside its limits.
  void set_joint(const std::string& joint, double angle);
  double joint_angle(const std::string& joint) const;
  // Rigid motion of the link from the seated posture to the current posture.
  Eigen::Isometry3d motion(const std::string& link) const;
  // True if `link` is `ancestor` or below it.
  bool descends_from(const std::string& link, const std::string& ancestor) const;

 private:
  std::filesystem::path path_;
  std::vector<SkeletonLink> links_;
  std::map<std::string, double> angles_;
};

}  // namespace hbm::deckgen
