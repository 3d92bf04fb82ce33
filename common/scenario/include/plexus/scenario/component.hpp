// Components: the unit a scenario composes (plants, sensors, reference generators,
// estimators, controllers).
//
// A component is built once from its validated YAML section (ComponentConfig), declares
// its input and output ports in its constructor, and then runs `step(k, t)` at its rate.
// `step` reads its inputs, writes its outputs and must not allocate. The same component
// object runs in `plexus sim` (in process, see executor.hpp) and, later, inside a DDS
// service in lockstep mode: the runner fills the inputs before `step` and publishes the
// outputs after it, so the component never knows where its data comes from.
//
// Ports are named relative to the component's robot: port `position` of a component on
// robot `r1` is the signal `r1/position`, and port `truth/state` is `r1/truth/state`,
// unless the scenario remaps it (`remap: {position: other/position}`). A port name with a
// '/' that does not start with `truth/` names a signal of its own (`other/state`).
//
// Every output names the IDL message type that carries it between processes (the topic's
// type, docs/topics.md); its fields are matched to that type's members by name (the signal
// fields of the type, generated from its IDL: docs/messages.md).
//
// Ports are declared in one of two ways:
// - typed (docs/sdk.md): `add_input<msg::PositionMeasurement>("position")` gives a port read as
//   the generated message type (`pos_->x()`), `add_output<msg::Pose2D>("estimate")` one written
//   as it (`out_->theta() = ...`); every member of the type is a field, checked at compile time;
// - by field names: `add_input("position", {"x", "y"}, "PositionMeasurement")`, read by index.
// Both are views of the same samples, so `plexus sim`, lockstep digests and metrics see no
// difference.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plexus/base/yaml_reader.hpp"
#include "plexus/msg/signal_layout.hpp"
#include "plexus/msg/type_support.hpp"
#include "plexus/scenario/signal.hpp"

namespace plexus::scenario {

/// What a component is; fixes where it may appear in a scenario and its execution stage.
/// Within one base step, stages run in this order (plants first, controllers last).
enum class ComponentKind { plant = 0, sensor = 1, reference = 2, estimator = 3, controller = 4 };

/// "plant", "sensor", "reference", "estimator", "controller".
const char* to_string(ComponentKind kind);

/// Everything a component factory gets: the section it is built from and its place in the run.
/// A warning about a scenario's configuration, raised by a component while it is built.
struct ScenarioWarning {
  std::string text;    ///< one short line: what and where ("controller: gain condition (15) not met")
  std::string detail;  ///< the full explanation (values, bounds, consequences); may be empty
};

struct ComponentConfig {
  std::string name;                          ///< instance name: `<robot>/plant`, `<robot>/<sensor>` or the service name
  std::string key;                           ///< its key in the scenario: the sensor or service name, or "plant"
  std::string robot;                         ///< robot it belongs to; empty for a robot-less service
  std::string type;                          ///< registered type name
  ComponentKind kind{};                      ///< kind of the registered type
  double base_step = 0.0;                    ///< s, the scenario's base step
  int64_t period_steps = 1;                  ///< runs every period_steps base steps
  uint64_t seed = 0;                         ///< its own seed (given, or derived from the scenario seed and `name`)
  std::map<std::string, std::string> remap;  ///< port -> signal name overrides from the scenario
  const YamlMap* section = nullptr;          ///< its YAML section: read your parameters from here
  /// Folder that relative file parameters are resolved against: the scenario file's (for a
  /// launched process, the original scenario's, not its part's; for a service on its own,
  /// its parameter file's).
  std::string base_dir;
  /// Where warn() collects: Scenario::warnings, kept until the whole scenario is valid, so
  /// a bad parameter gives its one-line error and nothing else.
  std::vector<ScenarioWarning>* warnings = nullptr;

  /// A warning about the configuration (a gain condition the parameters violate): `text` is
  /// one short line for the console, `detail` the full explanation for the run's records
  /// (scenario::log_warnings says where each goes).
  void warn(std::string text, std::string detail = {}) const;

  /// Period in seconds (period_steps * base_step).
  double period() const { return static_cast<double>(period_steps) * base_step; }
  /// The parameters: read every key you accept; the scenario loader rejects the rest.
  const YamlMap& params() const { return *section; }
  /// The signal a port binds to: the remap if any, else the port name if it contains '/',
  /// else `<robot>/<port>` (or `<port>` without a robot).
  std::string signal_for(const std::string& port) const;
};

/// A port: a signal name, the fields used, and the current sample.
class Port {
 public:
  Port(std::string port, std::string signal, std::vector<std::string> fields)
      : port_(std::move(port)), signal_(std::move(signal)), fields_(std::move(fields)) {}
  virtual ~Port() = default;
  Port(const Port&) = delete;
  Port& operator=(const Port&) = delete;

  const std::string& port() const { return port_; }
  const std::string& signal() const { return signal_; }
  const std::vector<std::string>& fields() const { return fields_; }
  /// For the runner: the sample it fills (inputs) or publishes (outputs).
  SignalSample& sample() { return sample_; }
  const SignalSample& sample() const { return sample_; }

 protected:
  std::string port_;
  std::string signal_;
  std::vector<std::string> fields_;
  SignalSample sample_;
};

/// An input: the latest sample of its signal that is due at this step (see executor.hpp).
class InputPort : public Port {
 public:
  InputPort(std::string port, std::string signal, std::vector<std::string> fields, std::string message)
      : Port(std::move(port), std::move(signal), std::move(fields)), message_(std::move(message)) {}
  /// The IDL message type it expects from another process; empty: only from its own process.
  const std::string& message() const { return message_; }
  /// Field i, in the order the component declared its fields.
  double operator[](std::size_t i) const { return sample_.values[i]; }
  /// False until the producer has produced its first sample.
  bool valid() const { return sample_.step >= 0; }
  /// The step whose sample this read asked for (the latest of the producer's steps the
  /// reading step may see; -1 before the first). sample().step equals it in `plexus sim` and
  /// lockstep; in realtime a sample that has not arrived yet leaves an older one here.
  int64_t due() const { return due_; }
  /// For the runner: sets due().
  void set_due(int64_t step) { due_ = step; }
  /// True for a typed port (add_input<T>): it reads the whole message, so a field its producer
  /// does not fill reads 0, as a member a producer does not use is 0 on the wire.
  bool whole_message() const { return whole_message_; }
  /// For the runner: the sample was filled for this step (a typed port decodes it). Must not allocate.
  virtual void refreshed() {}

 protected:
  bool whole_message_ = false;

 private:
  std::string message_;
  int64_t due_ = -1;
};

/// An output: the component writes every field at each of its steps.
class OutputPort : public Port {
 public:
  OutputPort(std::string port, std::string signal, std::vector<std::string> fields, std::string message)
      : Port(std::move(port), std::move(signal), std::move(fields)), message_(std::move(message)) {}
  double& operator[](std::size_t i) { return sample_.values[i]; }
  /// The IDL message type that carries it between processes; empty: in process only.
  const std::string& message() const { return message_; }
  /// Sets every field to zero (the default safe output). Must not allocate.
  virtual void clear() { sample_.values.fill(0.0); }
  /// For the runner: the component has written this step's output (a typed port encodes it).
  /// Must not allocate.
  virtual void commit() {}

 private:
  std::string message_;
};

/// A port's field names for a message type: its SignalLayout's.
template <class T>
std::vector<std::string> layout_fields() {
  const auto& f = msg::SignalLayout<T>::fields;
  return {f.begin(), f.end()};
}

/// An input read as its IDL message type: `in->x()`, `(*in).position()[1]`.
template <class T>
class TypedInput final : public InputPort {
 public:
  TypedInput(std::string port, std::string signal)
      : InputPort(std::move(port), std::move(signal), layout_fields<T>(), msg::type_support<T>().type_name) {
    whole_message_ = true;
  }
  const T& operator*() const { return value_; }
  const T* operator->() const { return &value_; }
  void refreshed() override { msg::SignalLayout<T>::load(sample_.values.data(), value_); }

 private:
  T value_{};
};

/// An output written as its IDL message type: `out->theta() = ...` (the header is the runtime's).
template <class T>
class TypedOutput final : public OutputPort {
 public:
  TypedOutput(std::string port, std::string signal)
      : OutputPort(std::move(port), std::move(signal), layout_fields<T>(), msg::type_support<T>().type_name) {}
  T& operator*() { return value_; }
  T* operator->() { return &value_; }
  void clear() override {
    value_ = T{};
    OutputPort::clear();
  }
  void commit() override { msg::SignalLayout<T>::store(value_, sample_.values.data()); }

 private:
  T value_{};
};

/// A parameter that may change while its component runs (`plexus param`, docs/parameters.md):
/// a gain, a threshold, a noise level; never a size or a model. `set` validates the value
/// with the validator the component's start uses and applies it, or throws (an InputError
/// or validation::ParameterError naming the key) and leaves the running value as it was.
/// Both run on the loop's thread, between two steps.
struct TunableParameter {
  std::string key;          ///< as in the component's YAML section ("L", "k1")
  std::string description;  ///< meaning and unit, one short line
  std::function<double()> get;
  std::function<void(double)> set;
};

class Component {
 public:
  explicit Component(const ComponentConfig& config);
  virtual ~Component() = default;
  Component(const Component&) = delete;
  Component& operator=(const Component&) = delete;

  /// Runs base step k at time t = k * base_step: read inputs, compute, write outputs.
  /// Must not allocate.
  virtual void step(int64_t k, double t) = 0;

  /// Realtime mode only: called instead of step() when an input this component reads from
  /// another process is older than its deadline. Writes the component's safe output. The
  /// default sets every output field to zero (zero velocity, zero torque); a controller
  /// that must hold something else overrides it. Must not allocate.
  virtual void hold(int64_t k, double t);

  /// Samples this component dropped by its documented rule for a late sample (realtime: a
  /// sample that arrived after the step that should have used it, docs/distributed.md);
  /// 0 for a component without such a rule. The realtime host reports the sum.
  virtual uint64_t dropped_late_samples() const { return 0; }

  const std::string& name() const { return name_; }
  /// The signal `port` would bind to without the scenario's remap.
  std::string default_signal(const std::string& port) const;
  const std::vector<std::unique_ptr<InputPort>>& inputs() const { return inputs_; }
  const std::vector<std::unique_ptr<OutputPort>>& outputs() const { return outputs_; }
  /// The parameters it lets change while it runs, in the order it declared them.
  const std::vector<TunableParameter>& tunables() const { return tunables_; }
  /// The tunable parameter `key`, or nullptr.
  const TunableParameter* tunable(const std::string& key) const;

 protected:
  /// Declares a parameter that may change while the component runs (see TunableParameter).
  void add_tunable(std::string key, std::string description, std::function<double()> get,
                   std::function<void(double)> set);
  /// Declares an input port that reads `fields` (by name) of the signal the port binds to,
  /// which arrives from another process as the IDL type `message` (empty: it must be
  /// produced in the same process).
  InputPort& add_input(const std::string& port, std::vector<std::string> fields, std::string message);
  /// Declares an output port producing a signal with these fields, carried between
  /// processes as the IDL message type `message` ("Pose2D"; empty: in process only).
  OutputPort& add_output(const std::string& port, std::vector<std::string> fields, std::string message);
  /// Declares an input read as the generated message type T (every member a field).
  template <class T>
  TypedInput<T>& add_input(const std::string& port) {
    auto in = std::make_unique<TypedInput<T>>(port, signal_of(port));
    TypedInput<T>& ref = *in;
    inputs_.push_back(std::move(in));
    return ref;
  }
  /// Declares an output written as the generated message type T.
  template <class T>
  TypedOutput<T>& add_output(const std::string& port) {
    auto out = std::make_unique<TypedOutput<T>>(port, signal_of(port));
    TypedOutput<T>& ref = *out;
    outputs_.push_back(std::move(out));
    return ref;
  }
  /// The signal `port` binds to (the scenario's remap, else `<robot>/<port>`).
  std::string signal_of(const std::string& port) const;

 private:
  std::string name_;
  std::string robot_;
  std::map<std::string, std::string> remap_;
  std::vector<std::unique_ptr<InputPort>> inputs_;
  std::vector<std::unique_ptr<OutputPort>> outputs_;
  std::vector<TunableParameter> tunables_;
};

}  // namespace plexus::scenario
