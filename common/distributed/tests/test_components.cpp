// Two tiny component types for the DDS tests of this folder (dds_test_support.hpp): a plant
// that echoes its command and a controller that follows the plant's state, so a test can
// see from one output sample which input the component was given.
//
//   test_echo_plant (plant)            in cmd {v, omega} (UnicycleCommand)
//                                      out truth/state {x, y, theta} (Pose2D) = {v, omega, 0}
//   test_follow_controller (controller) in truth/state {x, y, theta} (Pose2D)
//                                      out cmd {v, omega} (UnicycleCommand) = {x, 0.5};
//                                      hold(): Component's default safe output (all zero)
//   test_pass_estimator (estimator)    in truth/state {x, y, theta} (Pose2D), a measurement
//                                      out estimate {x, y, theta} (Pose2D) = truth/state
#include <memory>

#include "plexus/scenario/registry.hpp"

namespace plexus::distributed::testing {
namespace {

using scenario::Component;
using scenario::ComponentConfig;
using scenario::ComponentKind;
using scenario::InputPort;
using scenario::OutputPort;

class EchoPlant final : public Component {
 public:
  explicit EchoPlant(const ComponentConfig& c)
      : Component(c),
        cmd_(add_input("cmd", {"v", "omega"}, "UnicycleCommand")),
        out_(add_output("truth/state", {"x", "y", "theta"}, "Pose2D")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    out_[0] = cmd_[0];
    out_[1] = cmd_[1];
    out_[2] = 0.0;
  }

 private:
  InputPort& cmd_;
  OutputPort& out_;
};

class FollowController final : public Component {
 public:
  explicit FollowController(const ComponentConfig& c)
      : Component(c),
        state_(add_input("truth/state", {"x", "y", "theta"}, "Pose2D")),
        cmd_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    cmd_[0] = state_[0];
    cmd_[1] = 0.5;  // never zero when step() runs: a zero command is the hold
  }

 private:
  InputPort& state_;
  OutputPort& cmd_;
};

class PassEstimator final : public Component {
 public:
  explicit PassEstimator(const ComponentConfig& c)
      : Component(c),
        state_(add_input("truth/state", {"x", "y", "theta"}, "Pose2D")),
        out_(add_output("estimate", {"x", "y", "theta"}, "Pose2D")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    for (std::size_t i = 0; i < 3; ++i) out_[i] = state_[i];
  }

 private:
  InputPort& state_;
  OutputPort& out_;
};

const scenario::ComponentRegistration kEchoPlant{
    "test_echo_plant", ComponentKind::plant, "test: out truth/state {x, y, theta} = {cmd.v, cmd.omega, 0}",
    [](const ComponentConfig& c) { return std::make_unique<EchoPlant>(c); }};

const scenario::ComponentRegistration kFollowController{
    "test_follow_controller", ComponentKind::controller, "test: out cmd {v, omega} = {truth/state.x, 0.5}",
    [](const ComponentConfig& c) { return std::make_unique<FollowController>(c); }};

const scenario::ComponentRegistration kPassEstimator{
    "test_pass_estimator", ComponentKind::estimator, "test: out estimate {x, y, theta} = truth/state",
    [](const ComponentConfig& c) { return std::make_unique<PassEstimator>(c); }};

}  // namespace
}  // namespace plexus::distributed::testing
