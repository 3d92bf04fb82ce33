// measurement (sensor; plant_simulator): a sensor that fits any family. Parameters are
// documented in docs/scenarios.md.
//
//   reads `fields` of signal `source` (default: the robot's truth/state), adds
//   N(0, noise_std^2) to each field (Box-Muller on the sensor's own seed), then rounds each
//   field to the nearest multiple of `quantum` (0: no quantisation). Output:
//   `<robot>/<sensor name>` with the same fields, carried between processes as the IDL type
//   `message` (for example PositionMeasurement: the fields must be members of it,
//   docs/topics.md); without `message` it runs in `plexus sim` only.
#include <cmath>
#include <memory>
#include <string>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

class Measurement final : public Component {
 public:
  explicit Measurement(const ComponentConfig& c)
      : Component(c),
        noise_std_(optional_non_negative(c.params(), "noise_std")),
        quantum_(optional_non_negative(c.params(), "quantum")),
        rng_(c.seed),
        in_(add_input(c.params().optional<std::string>("source", "truth/state"),
                      required_names(c.params(), "fields", kMaxSignalFields),
                      "")),  // any signal of its own robot: read in its process
        out_(add_output(c.key, in_.fields(), c.params().optional<std::string>("message", ""))) {}

  void step(int64_t /*k*/, double /*t*/) override {
    for (std::size_t i = 0; i < in_.fields().size(); ++i) {
      double v = in_[i];
      if (noise_std_ > 0.0) v += noise_std_ * rng_.normal();
      if (quantum_ > 0.0) v = quantum_ * std::round(v / quantum_);
      out_[i] = v;
    }
  }

 private:
  double noise_std_;
  double quantum_;
  algorithms::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

const ComponentRegistration kMeasurement{"measurement", ComponentKind::sensor,
                                         "fields of a signal with Gaussian noise and quantisation",
                                         [](const ComponentConfig& c) { return std::make_unique<Measurement>(c); }};

}  // namespace
}  // namespace plexus::scenario
