#pragma once
// A multibody model's channels read by name in example tests: the channels' current values, and
// points of bodies in the world from the bodies' pose channels.
#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "models/channels.hpp"
#include "models/multibody/multibody_model.hpp"

namespace yardsim::testing {

// (model) => the channels' current values, by name
struct ChannelReader {
  std::map<std::string, models::Channel> byName;
  explicit ChannelReader(const models::MultibodyModel& mb) {
    std::vector<models::Channel> all;
    mb.channels(all);
    for (auto& c : all) byName.emplace(c.name, c);
  }
  double operator()(const std::string& name) const { return byName.at(name).read(); }
  // (body, point in the body frame, m) => the point in the world, m, from the body's channels
  // <body>.x|y|z and .roll|pitch|yaw (R_WB = Rz(yaw) Ry(pitch) Rx(roll))
  Eigen::Vector3d world(const std::string& b, const Eigen::Vector3d& p_B) const {
    const auto& r = *this;
    const Eigen::Matrix3d R_WB = (Eigen::AngleAxisd(r(b + ".yaw"), Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(r(b + ".pitch"), Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(r(b + ".roll"), Eigen::Vector3d::UnitX()))
                                     .toRotationMatrix();
    return Eigen::Vector3d(r(b + ".x"), r(b + ".y"), r(b + ".z")) + R_WB * p_B;
  }
};

}  // namespace yardsim::testing
