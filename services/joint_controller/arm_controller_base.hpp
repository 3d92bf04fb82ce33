// What both joint controllers of joint_controller (arm_vdc, arm_ct_pd) share (paper 004;
// docs/algorithms/arm.md): the reference and observer inputs and the cmd output.
//
//   in reference {q1.., dq1.., ddq1.., dddq1..} (JointReference), estimate {q1.., dq1..,
//     ddq1.., dddq1.., tau1.., dtau1.., phi1.., dphi1..} (LinkJointState);
//   out cmd {u1..un} (JointCommand)
// A command outside JointCommand's range (non-finite, or a torque the message cannot carry) is
// never published: the controller writes zero torque, says so (at most once a second), and
// write() returns false so that a controller with state restarts it.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_feedback.hpp"
#include "plexus/algorithms/arm/sine_reference.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/scenario/component.hpp"
#include "plexus/scenario/output_range.hpp"
#include "services/common/arm_fields.hpp"

namespace plexus::scenario {

// Shared by both controllers: reference and observer inputs, cmd output.
class ArmControllerBase : public Component {
 protected:
  ArmControllerBase(const ComponentConfig& c, int n)
      : Component(c),
        n_(n),
        ref_(add_input("reference", concat({names("q", n), names("dq", n), names("ddq", n), names("dddq", n)}),
                       "JointReference")),
        est_(add_input("estimate", estimate_fields(n), "LinkJointState")),
        cmd_(add_output("cmd", names("u", n), "JointCommand")),
        range_(cmd_),
        log_(named_logger("arm_controller")) {
    if (n > kMaxScenarioDof)
      c.params().fail("model", "has " + std::to_string(n) + " joints; at most " + std::to_string(kMaxScenarioDof));
    const Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    sample_ = {z, z, z, z};
    fb_ = algorithms::ArmFeedback::zero(n);
  }

  /// Reads the inputs; false until all of them have been produced.
  bool read() {
    if (!ref_.valid() || !est_.valid()) return false;
    for (int i = 0; i < n_; ++i) {
      const auto a = static_cast<std::size_t>(i);
      const auto n = static_cast<std::size_t>(n_);
      sample_.q(i) = ref_[a], sample_.qd(i) = ref_[n + a], sample_.qdd(i) = ref_[2 * n + a],
      sample_.qddd(i) = ref_[3 * n + a];
      fb_.q(i) = est_[a], fb_.qd(i) = est_[n + a], fb_.qdd(i) = est_[2 * n + a], fb_.qddd(i) = est_[3 * n + a];
      fb_.tau(i) = est_[4 * n + a], fb_.taud(i) = est_[5 * n + a], fb_.phi(i) = est_[6 * n + a],
      fb_.phid(i) = est_[7 * n + a];
    }
    return true;
  }
  /// Writes `u`, or zero torque (false) if `u` leaves the command's range.
  bool write(const Eigen::VectorXd& u) {
    for (int i = 0; i < n_; ++i) cmd_[static_cast<std::size_t>(i)] = u(i);
    const int bad = range_.first_violation(cmd_);
    if (bad < 0) return true;
    ++refused_;
    uint64_t held = 0;
    if (limiter_.allow(monotonic_ns(), held))
      log_->warn("{}: command u{} = {} out of range; zero torque instead, controller restarted ({} times{})", name(),
                 bad + 1, cmd_[static_cast<std::size_t>(bad)], refused_,
                 held ? ", " + std::to_string(held) + " not logged" : std::string());
    cmd_.clear();
    return false;
  }

  int n_;
  algorithms::ArmReferenceSample sample_;
  algorithms::ArmFeedback fb_;
  InputPort& ref_;
  InputPort& est_;
  OutputPort& cmd_;

 private:
  OutputRange range_;
  std::shared_ptr<spdlog::logger> log_;
  RateLimiter limiter_;
  uint64_t refused_ = 0;
};

}  // namespace plexus::scenario
