// arm_ekf (estimator; joint_controller): the indirect continuous EKF of the flexible-joint
// arm, state [tau, tau', phi, phi'] (paper 004 section 4.2; docs/algorithms/arm.md).
//
//   the arm model keys (services/common/arm_model_params.hpp: model, dof, length ..
//   stiffness, gravity, payload_mass) + q (4), r (0.1), p0 (1), substeps (1), jacobian
//   (full | paper), acceleration (model | differentiator), accel_filter_hz (50).
//   in joint_states {phi1.., dphi1..} (JointState), cmd {u1..} (JointCommand);
//   out estimate {q1.., dq1.., ddq1.., dddq1.., tau1.., dtau1.., phi1.., dphi1..} (LinkJointState).
//   At its first step it assumes steady motion: x^ = [C(phi, phi') phi' + G(phi), 0, phi, phi'].
//   An estimate that leaves LinkJointState's ranges (non-finite, or beyond what the message
//   carries: the filter diverged, e.g. under a restarted controller's torques of tens of kN m
//   at 1 kHz) or a non-finite covariance is never published: the filter restarts from the
//   latest sample as at its first step, and says so (at most once a second).
//   A tick whose joint_states sample is not new (in realtime, a sample that has not arrived)
//   predicts over the period with the model alone (FlexibleJointEkf::predict): the last
//   sample applied again as this period's measurement would pull the estimate back by a
//   period of motion. The estimate stays at the tick's time, so the controller beside it sees
//   one that advances every period.
#include <cstdint>
#include <memory>
#include <string>

#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/scenario/output_range.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/arm_fields.hpp"
#include "services/common/arm_model_params.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

alg::FlexibleJointEkfParams read_ekf(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  const std::string tuning = choice(p, "tuning", "robust", {"robust", "paper"});
  alg::FlexibleJointEkfParams e =
      tuning == "robust" ? alg::FlexibleJointEkfParams::robust() : alg::FlexibleJointEkfParams::paper();
  e.model = read_model(p);
  e.disturbance = p.optional<bool>("disturbance", e.disturbance);
  e.q_disturbance = p.optional<double>("q_disturbance", e.q_disturbance);
  e.q_tau_rate = p.optional<double>("q_tau_rate", e.q_tau_rate);
  e.payload = p.optional<bool>("payload", e.payload);
  e.q_payload = p.optional<double>("q_payload", e.q_payload);
  e.p0_payload = p.optional<double>("p0_payload", e.p0_payload);
  e.q = p.optional<double>("q", e.q);
  e.r = p.optional<double>("r", e.r);
  e.p0 = p.optional<double>("p0", e.p0);
  e.substeps = p.optional<int>("substeps", 1);
  e.step = c.period();
  e.accel_filter_hz = p.optional<double>("accel_filter_hz", e.accel_filter_hz);
  e.jacobian =
      choice(p, "jacobian", "full", {"full", "paper"}) == "full" ? alg::EkfJacobian::kFull : alg::EkfJacobian::kPaper;
  e.acceleration = choice(p, "acceleration", "model", {"model", "differentiator"}) == "model"
                       ? alg::LinkAcceleration::kModel
                       : alg::LinkAcceleration::kDifferentiator;
  return e;
}

class ArmEkfComponent final : public Component {
 public:
  explicit ArmEkfComponent(const ComponentConfig& c)
      : Component(c),
        ekf_(read_ekf(c)),
        rest_(ekf_params_model(c)),
        n_(ekf_.dof()),
        h_(c.period()),
        u_(Eigen::VectorXd::Zero(n_)),
        y_(Eigen::VectorXd::Zero(2 * n_)),
        x0_(Eigen::VectorXd::Zero(4 * n_)),
        g_(Eigen::VectorXd::Zero(n_)),
        zero_(Eigen::VectorXd::Zero(n_)),
        enc_(add_input("joint_states", concat({names("phi", n_), names("dphi", n_)}), "JointState")),
        cmd_(add_input("cmd", names("u", n_), "JointCommand")),
        estimate_(add_output("estimate", estimate_fields(n_), "LinkJointState")),
        range_(estimate_),
        log_(named_logger("arm_ekf")) {
    if (n_ > kMaxScenarioDof)
      c.params().fail("model", "has " + std::to_string(n_) + " joints; at most " + std::to_string(kMaxScenarioDof));
  }

  void step(int64_t /*k*/, double /*t*/) override {
    if (!enc_.valid()) return;
    const int64_t sample_step = enc_.sample().step;
    const bool new_sample = !started_ || sample_step > last_step_;
    for (int i = 0; i < n_; ++i) u_(i) = cmd_.valid() ? cmd_[static_cast<std::size_t>(i)] : 0.0;
    if (new_sample)
      for (int i = 0; i < 2 * n_; ++i) y_(i) = enc_[static_cast<std::size_t>(i)];
    if (!started_) {
      start();
    } else if (new_sample) {
      ekf_.update(u_, y_, h_);
    } else {
      ekf_.predict(u_, h_);
    }
    last_step_ = sample_step;
    publish();
    const int bad = range_.first_violation(estimate_);
    if (bad >= 0 || !ekf_.covariance().allFinite()) {
      ++restarts_;
      uint64_t held = 0;
      if (limiter_.allow(monotonic_ns(), held))
        log_->warn("{}: the estimate diverged ({} = {}); restarted from the latest joint sample ({} restarts{})",
                   name(), bad >= 0 ? estimate_.fields()[static_cast<std::size_t>(bad)] : std::string("covariance"),
                   bad >= 0 ? estimate_[static_cast<std::size_t>(bad)] : 0.0, restarts_,
                   held ? ", " + std::to_string(held) + " not logged" : std::string());
      start();
      publish();
    }
  }

 private:
  // Steady motion (at rest when phi' = 0): q ~ phi, q' ~ phi', q'' = 0, so
  // tau = C(q, q') q' + G(q) and tau' = 0 (the springs hold the arm).
  void start() {
    rest_.inverse_dynamics(y_.head(n_), y_.tail(n_), zero_, g_);  // C q' + G
    x0_ << g_, zero_, y_;
    ekf_.reset(x0_);
    started_ = true;
  }
  void publish() {
    const alg::ArmFeedback& fb = ekf_.feedback();
    for (int i = 0; i < n_; ++i) {
      const auto a = static_cast<std::size_t>(i);
      const auto n = static_cast<std::size_t>(n_);
      estimate_[a] = fb.q(i), estimate_[n + a] = fb.qd(i), estimate_[2 * n + a] = fb.qdd(i),
      estimate_[3 * n + a] = fb.qddd(i);
      estimate_[4 * n + a] = fb.tau(i), estimate_[5 * n + a] = fb.taud(i), estimate_[6 * n + a] = fb.phi(i),
                        estimate_[7 * n + a] = fb.phid(i);
    }
  }
  static alg::ArmModel ekf_params_model(const ComponentConfig& c) { return read_model(c.params()); }

  alg::FlexibleJointEkf ekf_;
  alg::ArmChainDynamics rest_;
  int n_;
  double h_;
  Eigen::VectorXd u_, y_, x0_, g_, zero_;
  int64_t last_step_ = -1;  // the producer's step of the last sample read
  bool started_ = false;
  InputPort& enc_;
  InputPort& cmd_;
  OutputPort& estimate_;
  OutputRange range_;
  std::shared_ptr<spdlog::logger> log_;
  RateLimiter limiter_;
  uint64_t restarts_ = 0;
};

const ComponentRegistration kArmEkf{"arm_ekf", ComponentKind::estimator,
                                    "indirect continuous EKF [tau, tau', phi, phi'] (paper 004 section 4.2)",
                                    [](const ComponentConfig& c) { return std::make_unique<ArmEkfComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
