// Registry entries of the flexible-joint arm family (paper 004; docs/algorithms/arm.md).
//
// Arm model keys, read by the plant (true arm) and by every model-based service (their
// nominal model), all optional:
//   model: paper_2dof | uniform        preset (default paper_2dof: Tables 1-2)
//   dof: n                             for `uniform` (n identical links, 1..4 in scenarios)
//   length, com, mass, inertia_o, twist, motor_inertia, friction, stiffness: lists of n
//                                      numbers overriding the preset, per link / joint
//   gravity: [gx, gy, gz]              m/s^2 in the base frame (default [9.81, 0, 0]: q = 0 hangs)
//   payload_mass                       kg at the tip of the last link (default 0)
//
//   flexible_joint_arm (plant): + q0 (list, default 0), dq0 (list, default 0: at rest): the
//       arm starts in steady motion at (q0, dq0), motors at dq0, springs holding C q' + G;
//       max_substep (s, default 1e-4: RK4 sub-step inside each plant period).
//       in cmd {u1..un} (JointCommand); out truth/state {q1..qn, dq1..dqn, phi1..phin,
//       dphi1..dphin, tau1..taun} (FlexibleJointTruth: link side, motor side, joint torque;
//       for metrics).
//   joint_encoders (sensor): dof (2), position_noise_std (rad, 0), velocity_noise_std
//       (rad/s, 0). in truth/state {phi.., dphi..}; out <sensor name> {phi1.., dphi1..}
//       (JointState, motor side: the scenarios name it joint_states).
//   arm_sine_reference (reference): amplitude, frequency_hz, offset, phase (lists; default
//       eq. (59)), dof (default 2). out reference {q1.., dq1.., ddq1.., dddq1..} (JointReference).
//   arm_ekf (estimator): model keys + q (4), r (0.1), p0 (1), substeps (1), jacobian
//       (full | paper), acceleration (model | differentiator), accel_filter_hz (50).
//       in joint_states {phi1.., dphi1..}, cmd {u1..};
//       out estimate {q1.., dq1.., ddq1.., dddq1.., tau1.., dtau1.., phi1.., dphi1..} (LinkJointState).
//       At its first step it assumes steady motion: x^ = [C(phi, phi') phi' + G(phi), 0, phi, phi'].
//   arm_vdc (controller): model keys + k_b, rho, lambda, k_p, k_i, ts_min, ts_max, lambda_q,
//       lambda_phi, lambda_tau, k_phi, k_tau (lists; default Table 3), theta_lower (0.6),
//       theta_upper (1.8), theta_initial (1.0). in reference, estimate; out cmd.
//   arm_ct_pd (controller): model keys + k_p, k_v, k_d (lists; default eq. (60)'s gains),
//       velocity (motor | link, default motor). in reference, estimate; out cmd.
#include <memory>
#include <string>
#include <vector>

#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/sine_reference.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

// The joint messages hold 16 joints (idl/plexus/msg/joint.idl, MAX_JOINTS), and the estimate
// (8 fields per joint) fills a signal of kMaxSignalFields; the algorithms take any n.
constexpr int kMaxScenarioDof = 16;
static_assert(8 * kMaxScenarioDof <= static_cast<int>(kMaxSignalFields));

/// The estimate's fields (LinkJointState): link motion to the jerk, joint torque and rate,
/// motor side.
std::vector<std::string> estimate_fields(int n);

std::vector<std::string> names(const std::string& prefix, int n) {
  std::vector<std::string> out;
  for (int i = 1; i <= n; ++i) out.push_back(prefix + std::to_string(i));
  return out;
}

std::vector<std::string> concat(std::initializer_list<std::vector<std::string>> parts) {
  std::vector<std::string> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

std::vector<std::string> estimate_fields(int n) {
  return concat({names("q", n), names("dq", n), names("ddq", n), names("dddq", n), names("tau", n), names("dtau", n),
                 names("phi", n), names("dphi", n)});
}

/// Optional list of `n` numbers; `fallback` when absent.
Eigen::VectorXd number_list(const YamlMap& p, const std::string& key, int n, const Eigen::VectorXd& fallback) {
  if (!p.has(key)) return fallback;
  const auto items = p.sequence(key);
  if (static_cast<int>(items.size()) != n) p.fail(key, "needs " + std::to_string(n) + " numbers (one per joint)");
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) {
    try {
      v(i) = items[static_cast<std::size_t>(i)].as<double>();
    } catch (const YAML::Exception&) {
      p.fail(key, "expected a list of numbers");
    }
  }
  return v;
}

alg::ArmModel read_model(const YamlMap& p) {
  const std::string preset = p.optional<std::string>("model", "paper_2dof");
  alg::ArmModel m;
  if (preset == "paper_2dof") {
    m = alg::ArmModel::paper_2dof();
  } else if (preset == "uniform") {
    const int n = p.optional<int>("dof", 2);
    if (n < 1 || n > kMaxScenarioDof) p.fail("dof", "must be in 1.." + std::to_string(kMaxScenarioDof));
    m = alg::ArmModel::uniform_chain(n);
  } else {
    p.fail("model", "must be paper_2dof or uniform");
  }
  if (preset == "paper_2dof" && p.has("dof") && p.optional<int>("dof", 2) != 2) p.fail("dof", "is 2 for model paper_2dof");
  const int n = m.dof();
  auto apply = [&](const std::string& key, auto member, auto& items) {
    Eigen::VectorXd current(n);
    for (int i = 0; i < n; ++i) current(i) = items[static_cast<std::size_t>(i)].*member;
    const Eigen::VectorXd v = number_list(p, key, n, current);
    for (int i = 0; i < n; ++i) items[static_cast<std::size_t>(i)].*member = v(i);
  };
  apply("length", &alg::ArmLink::length, m.links);
  apply("com", &alg::ArmLink::com, m.links);
  apply("mass", &alg::ArmLink::mass, m.links);
  apply("inertia_o", &alg::ArmLink::inertia_o, m.links);
  apply("twist", &alg::ArmLink::twist, m.links);
  apply("motor_inertia", &alg::ArmJoint::motor_inertia, m.joints);
  apply("friction", &alg::ArmJoint::friction, m.joints);
  apply("stiffness", &alg::ArmJoint::stiffness, m.joints);
  m.gravity = number_list(p, "gravity", 3, m.gravity);
  m.payload_mass = p.optional<double>("payload_mass", 0.0);
  m.validate();
  return m;
}

void read_into(const YamlMap& p, const std::string& key, Eigen::VectorXd& v) { v = number_list(p, key, static_cast<int>(v.size()), v); }

// ---------------------------------------------------------------------------------------
class FlexibleJointArmComponent final : public Component {
 public:
  explicit FlexibleJointArmComponent(const ComponentConfig& c)
      : Component(c),
        plant_({read_model(c.params()), c.params().optional<double>("max_substep", 1e-4)}),
        n_(plant_.dof()),
        h_(c.period()),
        u_(Eigen::VectorXd::Zero(n_)),
        tau_(Eigen::VectorXd::Zero(n_)),
        cmd_(add_input("cmd", names("u", n_), "JointCommand")),
        state_(add_output("truth/state",
                          concat({names("q", n_), names("dq", n_), names("phi", n_), names("dphi", n_), names("tau", n_)}),
                          "FlexibleJointTruth")) {
    if (n_ > kMaxScenarioDof) c.params().fail("model", "has " + std::to_string(n_) + " joints; at most " + std::to_string(kMaxScenarioDof));
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n_);
    plant_.reset_in_motion(number_list(c.params(), "q0", n_, zero), number_list(c.params(), "dq0", n_, zero));
  }

  void step(int64_t k, double /*t*/) override {
    if (k > 0) {
      // The arm moves whether or not a command arrived: without one (realtime, before the
      // first command) its drives hold the last torque (zero at first).
      if (cmd_.valid())
        for (int i = 0; i < n_; ++i) u_(i) = cmd_[static_cast<std::size_t>(i)];
      plant_.step(u_, h_);
    }
    const alg::FlexibleJointArmState& s = plant_.state();
    plant_.spring_torque(tau_);
    const auto n = static_cast<std::size_t>(n_);
    for (int i = 0; i < n_; ++i) {
      const auto a = static_cast<std::size_t>(i);
      state_[a] = s.q(i), state_[n + a] = s.qd(i);
      state_[2 * n + a] = s.phi(i), state_[3 * n + a] = s.phid(i);
      state_[4 * n + a] = tau_(i);
    }
  }

 private:
  alg::FlexibleJointArmPlant plant_;
  int n_;
  double h_;
  Eigen::VectorXd u_, tau_;
  InputPort& cmd_;
  OutputPort& state_;
};

// ---------------------------------------------------------------------------------------
/// The motor encoders: phi and phi' of every joint, with optional Gaussian noise (position
/// noises drawn first, then velocity, from the sensor's own seed).
class JointEncodersComponent final : public Component {
 public:
  explicit JointEncodersComponent(const ComponentConfig& c)
      : Component(c),
        n_(dof(c.params())),
        position_std_(optional_non_negative(c.params(), "position_noise_std")),
        velocity_std_(optional_non_negative(c.params(), "velocity_noise_std")),
        rng_(c.seed),
        in_(add_input("truth/state", concat({names("phi", n_), names("dphi", n_)}), "FlexibleJointTruth")),
        out_(add_output(c.key, concat({names("phi", n_), names("dphi", n_)}), "JointState")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const auto n = static_cast<std::size_t>(n_);
    for (std::size_t i = 0; i < n; ++i) out_[i] = position_std_ > 0.0 ? in_[i] + position_std_ * rng_.normal() : in_[i];
    for (std::size_t i = n; i < 2 * n; ++i)
      out_[i] = velocity_std_ > 0.0 ? in_[i] + velocity_std_ * rng_.normal() : in_[i];
  }

 private:
  static int dof(const YamlMap& p) {
    const int n = p.optional<int>("dof", 2);
    if (n < 1 || n > kMaxScenarioDof) p.fail("dof", "must be in 1.." + std::to_string(kMaxScenarioDof));
    return n;
  }
  int n_;
  double position_std_, velocity_std_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

// ---------------------------------------------------------------------------------------
alg::ArmSineReferenceParams read_reference(const YamlMap& p) {
  const int n = p.optional<int>("dof", 2);
  if (n < 1 || n > kMaxScenarioDof) p.fail("dof", "must be in 1.." + std::to_string(kMaxScenarioDof));
  alg::ArmSineReferenceParams r = alg::ArmSineReferenceParams::paper(n);
  read_into(p, "amplitude", r.amplitude);
  read_into(p, "frequency_hz", r.frequency_hz);
  read_into(p, "offset", r.offset);
  read_into(p, "phase", r.phase);
  return r;
}

class ArmSineReferenceComponent final : public Component {
 public:
  explicit ArmSineReferenceComponent(const ComponentConfig& c)
      : Component(c),
        ref_(read_reference(c.params())),
        n_(ref_.dof()),
        out_(add_output("reference", concat({names("q", n_), names("dq", n_), names("ddq", n_), names("dddq", n_)}),
                        "JointReference")) {
    ref_.sample(0.0, sample_);
  }

  void step(int64_t /*k*/, double t) override {
    ref_.sample(t, sample_);
    for (int i = 0; i < n_; ++i) {
      out_[static_cast<std::size_t>(i)] = sample_.q(i);
      out_[static_cast<std::size_t>(n_ + i)] = sample_.qd(i);
      out_[static_cast<std::size_t>(2 * n_ + i)] = sample_.qdd(i);
      out_[static_cast<std::size_t>(3 * n_ + i)] = sample_.qddd(i);
    }
  }

 private:
  alg::ArmSineReference ref_;
  int n_;
  alg::ArmReferenceSample sample_;
  OutputPort& out_;
};

// ---------------------------------------------------------------------------------------
alg::FlexibleJointEkfParams read_ekf(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  alg::FlexibleJointEkfParams e;
  e.model = read_model(p);
  e.q = p.optional<double>("q", e.q);
  e.r = p.optional<double>("r", e.r);
  e.p0 = p.optional<double>("p0", e.p0);
  e.substeps = p.optional<int>("substeps", 1);
  e.step = c.period();
  e.accel_filter_hz = p.optional<double>("accel_filter_hz", e.accel_filter_hz);
  const std::string jac = p.optional<std::string>("jacobian", "full");
  if (jac != "full" && jac != "paper") p.fail("jacobian", "must be full or paper");
  e.jacobian = jac == "full" ? alg::EkfJacobian::kFull : alg::EkfJacobian::kPaper;
  const std::string acc = p.optional<std::string>("acceleration", "model");
  if (acc != "model" && acc != "differentiator") p.fail("acceleration", "must be model or differentiator");
  e.acceleration = acc == "model" ? alg::LinkAcceleration::kModel : alg::LinkAcceleration::kDifferentiator;
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
        enc_(add_input("joint_states", concat({names("phi", n_), names("dphi", n_)}), "JointState")),
        cmd_(add_input("cmd", names("u", n_), "JointCommand")),
        estimate_(add_output("estimate", estimate_fields(n_), "LinkJointState")) {
    if (n_ > kMaxScenarioDof) c.params().fail("model", "has " + std::to_string(n_) + " joints; at most " + std::to_string(kMaxScenarioDof));
  }

  void step(int64_t /*k*/, double /*t*/) override {
    if (!enc_.valid()) return;
    for (int i = 0; i < 2 * n_; ++i) y_(i) = enc_[static_cast<std::size_t>(i)];
    if (!started_) {
      // Steady motion (at rest when phi' = 0): q ~ phi, q' ~ phi', q'' = 0, so
      // tau = C(q, q') q' + G(q) and tau' = 0 (the springs hold the arm).
      const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n_);
      rest_.bias(y_.head(n_), y_.tail(n_), g_);
      x0_ << g_, zero, y_;
      ekf_.reset(x0_);
      started_ = true;
    } else {
      for (int i = 0; i < n_; ++i) u_(i) = cmd_.valid() ? cmd_[static_cast<std::size_t>(i)] : 0.0;
      ekf_.update(u_, y_, h_);
    }
    const alg::ArmFeedback& fb = ekf_.feedback();
    for (int i = 0; i < n_; ++i) {
      const auto a = static_cast<std::size_t>(i);
      const auto n = static_cast<std::size_t>(n_);
      estimate_[a] = fb.q(i), estimate_[n + a] = fb.qd(i), estimate_[2 * n + a] = fb.qdd(i), estimate_[3 * n + a] = fb.qddd(i);
      estimate_[4 * n + a] = fb.tau(i), estimate_[5 * n + a] = fb.taud(i), estimate_[6 * n + a] = fb.phi(i),
                        estimate_[7 * n + a] = fb.phid(i);
    }
  }

 private:
  static alg::ArmModel ekf_params_model(const ComponentConfig& c) { return read_model(c.params()); }

  alg::FlexibleJointEkf ekf_;
  alg::ArmRigidBodyDynamics rest_;
  int n_;
  double h_;
  Eigen::VectorXd u_, y_, x0_, g_;
  bool started_ = false;
  InputPort& enc_;
  InputPort& cmd_;
  OutputPort& estimate_;
};

// ---------------------------------------------------------------------------------------
// Shared by both controllers: reference and observer inputs, cmd output.
class ArmControllerBase : public Component {
 protected:
  ArmControllerBase(const ComponentConfig& c, int n)
      : Component(c),
        n_(n),
        ref_(add_input("reference", concat({names("q", n), names("dq", n), names("ddq", n), names("dddq", n)}), "JointReference")),
        est_(add_input("estimate", estimate_fields(n), "LinkJointState")),
        cmd_(add_output("cmd", names("u", n), "JointCommand")) {
    if (n > kMaxScenarioDof) c.params().fail("model", "has " + std::to_string(n) + " joints; at most " + std::to_string(kMaxScenarioDof));
    const Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    sample_ = {z, z, z, z};
    fb_ = alg::ArmFeedback::zero(n);
  }

  /// Reads the inputs; false until all of them have been produced.
  bool read() {
    if (!ref_.valid() || !est_.valid()) return false;
    for (int i = 0; i < n_; ++i) {
      const auto a = static_cast<std::size_t>(i);
      const auto n = static_cast<std::size_t>(n_);
      sample_.q(i) = ref_[a], sample_.qd(i) = ref_[n + a], sample_.qdd(i) = ref_[2 * n + a], sample_.qddd(i) = ref_[3 * n + a];
      fb_.q(i) = est_[a], fb_.qd(i) = est_[n + a], fb_.qdd(i) = est_[2 * n + a], fb_.qddd(i) = est_[3 * n + a];
      fb_.tau(i) = est_[4 * n + a], fb_.taud(i) = est_[5 * n + a], fb_.phi(i) = est_[6 * n + a], fb_.phid(i) = est_[7 * n + a];
    }
    return true;
  }
  void write(const Eigen::VectorXd& u) {
    for (int i = 0; i < n_; ++i) cmd_[static_cast<std::size_t>(i)] = u(i);
  }

  int n_;
  alg::ArmReferenceSample sample_;
  alg::ArmFeedback fb_;
  InputPort& ref_;
  InputPort& est_;
  OutputPort& cmd_;
};

alg::VdcParams read_vdc(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  const alg::ArmModel model = read_model(p);
  alg::VdcParams v = p.optional<std::string>("model", "paper_2dof") == "paper_2dof" ? alg::VdcParams::paper_2dof()
                                                                                     : alg::VdcParams::uniform(model);
  v.model = model;
  for (auto [key, vec] : {std::pair{"k_b", &v.k_b}, {"rho", &v.rho}, {"lambda", &v.lambda}, {"k_p", &v.k_p},
                          {"k_i", &v.k_i}, {"ts_min", &v.ts_min}, {"ts_max", &v.ts_max}, {"lambda_q", &v.lambda_q},
                          {"lambda_phi", &v.lambda_phi}, {"lambda_tau", &v.lambda_tau}, {"k_phi", &v.k_phi},
                          {"k_tau", &v.k_tau}}) {
    read_into(p, key, *vec);
  }
  v.theta_lower = p.optional<double>("theta_lower", v.theta_lower);
  v.theta_upper = p.optional<double>("theta_upper", v.theta_upper);
  v.theta_initial = p.optional<double>("theta_initial", v.theta_initial);
  v.step = c.period();
  return v;
}

class ArmVdcComponent final : public ArmControllerBase {
 public:
  explicit ArmVdcComponent(const ComponentConfig& c) : ArmVdcComponent(c, read_vdc(c)) {}
  void step(int64_t /*k*/, double /*t*/) override {
    if (read()) write(vdc_.step(sample_, fb_));
  }

 private:
  ArmVdcComponent(const ComponentConfig& c, const alg::VdcParams& p) : ArmControllerBase(c, p.model.dof()), vdc_(p) {}
  alg::VdcController vdc_;
};

alg::CtPdParams read_ct_pd(const YamlMap& p) {
  alg::CtPdParams v = alg::CtPdParams::paper_2dof();
  v.model = read_model(p);
  const int n = v.model.dof();
  if (n != 2) v.k_p = v.k_v = v.k_d = Eigen::VectorXd::Zero(n);
  read_into(p, "k_p", v.k_p);
  read_into(p, "k_v", v.k_v);
  read_into(p, "k_d", v.k_d);
  const std::string vel = p.optional<std::string>("velocity", "motor");
  if (vel != "motor" && vel != "link") p.fail("velocity", "must be motor or link");
  v.velocity = vel == "motor" ? alg::CtPdVelocity::kMotor : alg::CtPdVelocity::kLink;
  return v;
}

class ArmCtPdComponent final : public ArmControllerBase {
 public:
  explicit ArmCtPdComponent(const ComponentConfig& c) : ArmCtPdComponent(c, read_ct_pd(c.params())) {}
  void step(int64_t /*k*/, double /*t*/) override {
    if (read()) write(ctpd_.step(sample_, fb_));
  }

 private:
  ArmCtPdComponent(const ComponentConfig& c, const alg::CtPdParams& p) : ArmControllerBase(c, p.model.dof()), ctpd_(p) {}
  alg::CtPdController ctpd_;
};

const ComponentRegistration kArmPlant{
    "flexible_joint_arm", ComponentKind::plant,
    "n-DoF flexible-joint arm (paper 004), KDL dynamics, RK4 sub-steps; in cmd, out truth/state",
    [](const ComponentConfig& c) { return std::make_unique<FlexibleJointArmComponent>(c); }};
const ComponentRegistration kJointEncoders{
    "joint_encoders", ComponentKind::sensor, "motor encoders: phi and phi' per joint with optional noise",
    [](const ComponentConfig& c) { return std::make_unique<JointEncodersComponent>(c); }};
const ComponentRegistration kArmReference{
    "arm_sine_reference", ComponentKind::reference, "joint sinusoids q_d with 3 derivatives (paper 004 eq. (59))",
    [](const ComponentConfig& c) { return std::make_unique<ArmSineReferenceComponent>(c); }};
const ComponentRegistration kArmEkf{
    "arm_ekf", ComponentKind::estimator, "indirect continuous EKF [tau, tau', phi, phi'] (paper 004 section 4.2)",
    [](const ComponentConfig& c) { return std::make_unique<ArmEkfComponent>(c); }};
const ComponentRegistration kArmVdc{
    "arm_vdc", ComponentKind::controller, "virtual decomposition control (paper 004 eqs. (9)-(23))",
    [](const ComponentConfig& c) { return std::make_unique<ArmVdcComponent>(c); }};
const ComponentRegistration kArmCtPd{
    "arm_ct_pd", ComponentKind::controller, "computed torque + PD comparator (paper 004 eq. (60))",
    [](const ComponentConfig& c) { return std::make_unique<ArmCtPdComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
