// The data path of one service, in process and without DDS: its own document (a part of a
// scenario, as service_main loads it), the edge check every subscriber runs on a received
// message (InputGuard::accept -> WireSignal::decode, common/distributed/src/input_guard.hpp),
// the step executor that fills the component's inputs and steps it (StepExecutor, as the
// realtime and lockstep hosts do), and the encoding its publisher applies to each output
// (WireSignal::encode). Only the DDS reader and writer are left out: a test hands a typed IDL
// message to deliver() where a WireSubscriber would take() one, and reads the message a
// WirePublisher would write with published<M>().
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "input_guard.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::services_test {

using distributed::Rejection;
using scenario::SignalSample;

/// The component types whose data path a test file covers, with the file's service: each
/// services/<executable>/tests/<executable>_test.cpp names its types once with a `Covers`,
/// and coverage_test.cpp checks that every registered type is named (a new type of a
/// service's folder is untested until its own test file says so).
inline std::map<std::string, std::string>& covered_types() {
  static std::map<std::string, std::string> types;
  return types;
}
struct Covers {
  Covers(std::initializer_list<const char*> types, const char* file = __builtin_FILE()) {
    for (const char* t : types) covered_types().emplace(t, file);
  }
};

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// The refusals are asserted, not read: the guard's warning lines (and the components'
/// start-up notes) are kept off the test output.
inline const bool kQuietLogs = [] {
  spdlog::set_level(spdlog::level::err);
  return true;
}();

/// Loads a service's own document as service_main does: a part of a scenario
/// (LoadOptions::partial: inputs nobody here produces come from other processes), with
/// `--set` overrides.
inline scenario::Scenario load_part(const std::string& yaml, const std::vector<std::string>& sets = {}) {
  std::vector<scenario::Override> o;
  for (const auto& s : sets) o.push_back(scenario::parse_override(s));
  return scenario::load_scenario_text(yaml, "part.yaml", o, {.partial = true});
}

/// The configuration error (InputError) of loading `yaml` with `sets`, or "no error".
inline std::string config_error(const std::string& yaml, const std::vector<std::string>& sets) {
  try {
    load_part(yaml, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// A bad parameter and what its error must name.
struct BadParam {
  std::string set;                    ///< `--set` argument, "services.obs.L=-1"
  std::vector<std::string> mentions;  ///< substrings of the error (the key, its section)
};

/// Each bad parameter is a configuration error naming its key.
inline void expect_config_errors(const std::string& yaml, const std::vector<BadParam>& table) {
  ASSERT_EQ(config_error(yaml, {}), "no error") << "the base document must be valid";
  for (const auto& bad : table) {
    const std::string e = config_error(yaml, {bad.set});
    EXPECT_NE(e, "no error") << bad.set;
    for (const auto& m : bad.mentions) EXPECT_NE(e.find(m), std::string::npos) << bad.set << " -> " << e;
  }
}

/// One service process, DDS left out (see the file comment).
class ServiceUnderTest {
 public:
  /// `hosted`: names of the components that run here (empty: all of them); the outputs of
  /// the others arrive as messages through deliver(), as over DDS.
  explicit ServiceUnderTest(const std::string& yaml, const std::vector<std::string>& hosted = {},
                            const std::vector<std::string>& sets = {})
      : sc_(load_part(yaml, sets)), step_ns_(std::llround(sc_.step * 1e9)) {
    std::vector<bool> h;
    if (!hosted.empty()) {
      for (const auto& c : sc_.components) {
        bool here = false;
        for (const auto& n : hosted) here = here || c.component->name() == n;
        h.push_back(here);
      }
    }
    exec_ = std::make_unique<scenario::StepExecutor>(sc_, h);
    const auto& signals = exec_->signals();
    wires_.resize(signals.size());
    latest_.resize(signals.size());
    for (std::size_t i = 0; i < signals.size(); ++i) {
      index_[signals[i].name] = i;
      if (!signals[i].message.empty()) wires_[i] = std::make_unique<distributed::WireSignal>(signals[i], step_ns_);
    }
    for (std::size_t i : exec_->remote_inputs()) remote_.push_back(signals[i].name);
  }

  int64_t step_ns() const { return step_ns_; }
  double base_step() const { return sc_.step; }
  const scenario::Scenario& scenario() const { return sc_; }
  /// The signals the hosted components read from other processes.
  const std::vector<std::string>& remote_inputs() const { return remote_; }

  /// A message of type M stamped for step k (the header's data time, as a publisher stamps it).
  template <class M>
  M stamped(int64_t k) const {
    M m;
    m.header().data_time_ns(k * step_ns_);
    return m;
  }

  /// Hands a received message of input `signal` to the edge check the services' subscribers
  /// run (InputGuard::accept: WireSignal::decode, refusals counted). Accepted, it is the
  /// sample the next step reads (realtime hosts: the latest accepted sample). Returns why it
  /// was refused, Rejection::none if accepted.
  Rejection deliver(const std::string& signal, const void* message) {
    const std::size_t i = remote_index(signal);
    SignalSample probe = latest_[i];
    std::size_t bad = 0;
    const Rejection why = wires_[i]->decode(message, probe, bad);
    const bool accepted = guard_.accept(*wires_[i], message, latest_[i]);
    EXPECT_EQ(accepted, why == Rejection::none) << signal;
    return why;
  }
  template <class M>
  Rejection deliver(const std::string& signal, const M& message) {
    return deliver(signal, static_cast<const void*>(&message));
  }

  /// Runs base step k of the hosted components.
  void step(int64_t k) {
    exec_->step(
        k, [this](std::size_t s, int64_t, SignalSample& out) { out = latest_[s]; },
        [this](std::size_t s, const SignalSample& sample) { latest_[s] = sample; });
  }

  /// The latest sample of an output signal.
  const SignalSample& sample(const std::string& signal) const { return latest_.at(index(signal)); }
  /// Field `field` of an output's latest sample.
  double out(const std::string& signal, const std::string& field) const {
    const std::size_t i = index(signal);
    const auto& f = exec_->signals()[i].fields;
    for (std::size_t j = 0; j < f.size(); ++j)
      if (f[j] == field) return latest_[i].values[j];
    ADD_FAILURE() << signal << " has no field " << field;
    return kNaN;
  }
  /// The fields of a signal, in order.
  const std::vector<std::string>& fields(const std::string& signal) const {
    return exec_->signals()[index(signal)].fields;
  }
  /// The IDL message type a signal travels as.
  const std::string& message_type(const std::string& signal) const { return exec_->signals()[index(signal)].message; }

  /// The latest sample of an output as the message its publisher writes (WireSignal::encode).
  template <class M>
  M published(const std::string& signal) const {
    const std::size_t i = index(signal);
    EXPECT_TRUE(wires_[i]) << signal << " travels in process only";
    M m;
    if (wires_[i]) wires_[i]->encode(latest_[i], &m);
    return m;
  }

  /// The edge check a consumer in another process runs on this output's latest sample.
  Rejection check_output(const std::string& signal) const {
    const std::size_t i = index(signal);
    const distributed::MessagePtr m = wires_[i]->make_message();
    wires_[i]->encode(latest_[i], m.get());
    SignalSample s;
    std::size_t bad = 0;
    return wires_[i]->decode(m.get(), s, bad);
  }

  /// Samples refused so far.
  uint64_t rejected() const { return guard_.rejected(); }

 private:
  std::size_t index(const std::string& signal) const {
    const auto it = index_.find(signal);
    if (it == index_.end()) throw std::out_of_range("no signal " + signal);
    return it->second;
  }
  std::size_t remote_index(const std::string& signal) const {
    const std::size_t i = index(signal);
    bool remote = false;
    for (const auto& r : remote_) remote = remote || r == signal;
    if (!remote || !wires_[i]) throw std::out_of_range(signal + " is not an input from another process");
    return i;
  }

  scenario::Scenario sc_;
  int64_t step_ns_;
  std::unique_ptr<scenario::StepExecutor> exec_;
  std::vector<std::unique_ptr<distributed::WireSignal>> wires_;  // by signal (null: in process only)
  std::vector<SignalSample> latest_;                             // by signal
  std::map<std::string, std::size_t> index_;
  std::vector<std::string> remote_;
  distributed::detail::InputGuard guard_{"services test"};
};

// --- bad samples --------------------------------------------------------------------

/// Delivers the good messages of step k (every input the service reads).
using Feed = std::function<void(ServiceUnderTest&, int64_t k)>;

/// A bad message for step k, and the edge check's verdict on it.
struct BadSample {
  std::string what;
  std::function<Rejection(ServiceUnderTest&, int64_t k)> deliver;
  Rejection expected;
};

/// The output samples of steps 0..steps-1, feeding `feed(k)` before each step. With `bad`,
/// it is delivered at step `at` after the good messages (so, were it accepted, it would
/// replace them and the step would read it) and must be refused with its expected verdict.
inline std::vector<SignalSample> run_steps(const std::string& yaml, const std::vector<std::string>& hosted,
                                           const std::vector<std::string>& outputs, int64_t steps, const Feed& feed,
                                           const BadSample* bad = nullptr, int64_t at = -1) {
  ServiceUnderTest s(yaml, hosted);
  std::vector<SignalSample> log;
  for (int64_t k = 0; k < steps; ++k) {
    feed(s, k);
    if (bad && k == at) {
      EXPECT_EQ(bad->deliver(s, k), bad->expected) << bad->what;
      EXPECT_EQ(s.rejected(), 1u) << bad->what;
    }
    s.step(k);
    for (const auto& o : outputs) log.push_back(s.sample(o));
  }
  return log;
}

/// Every bad sample of `table` is refused at the edge, and the run's outputs are bit for bit
/// those of the run without it: the component's state never saw it.
inline void expect_refused_without_effect(const std::string& yaml, const std::vector<std::string>& hosted,
                                          const std::vector<std::string>& outputs, int64_t steps, int64_t at,
                                          const Feed& feed, const std::vector<BadSample>& table) {
  const auto clean = run_steps(yaml, hosted, outputs, steps, feed);
  for (const auto& bad : table) {
    const auto dirty = run_steps(yaml, hosted, outputs, steps, feed, &bad, at);
    ASSERT_EQ(clean.size(), dirty.size());
    for (std::size_t i = 0; i < clean.size(); ++i) {
      EXPECT_EQ(clean[i].step, dirty[i].step) << bad.what << ", sample " << i;
      for (std::size_t f = 0; f < scenario::kMaxSignalFields; ++f)
        if (!(clean[i].values[f] == dirty[i].values[f] ||
              (std::isnan(clean[i].values[f]) && std::isnan(dirty[i].values[f])))) {
          ADD_FAILURE() << bad.what << ": sample " << i << " field " << f << ": " << clean[i].values[f] << " vs "
                        << dirty[i].values[f];
          break;
        }
    }
  }
}

/// The largest absolute difference between two vectors-like of equal size.
template <class A, class B>
double max_abs_diff(const A& a, const B& b, std::size_t n) {
  double d = 0.0;
  for (std::size_t i = 0; i < n; ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace plexus::services_test
