// arm_sine_reference (reference; component_host): the joint sinusoids q_d of paper 004
// eq. (59) with three derivatives (docs/algorithms/arm.md). The output binds to
// `<robot>/reference` unless remapped and names its IDL type (docs/topics.md).
//
//   amplitude, frequency_hz, offset, phase (lists of dof numbers; default eq. (59)),
//   dof (default 2).
//   out reference {q1.., dq1.., ddq1.., dddq1..} (JointReference).
#include <memory>
#include <string>

#include "plexus/algorithms/arm/sine_reference.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/arm_fields.hpp"
#include "services/common/arm_model_params.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

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

const ComponentRegistration kArmReference{
    "arm_sine_reference", ComponentKind::reference, "joint sinusoids q_d with 3 derivatives (paper 004 eq. (59))",
    [](const ComponentConfig& c) { return std::make_unique<ArmSineReferenceComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
