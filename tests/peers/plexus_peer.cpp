// plexus_test_peer: a plexus process that publishes or subscribes every message type
// (or one), for the multi-process and cross-vendor tests.
//
//   plexus_test_peer pub --dds fast --domain 11 --count 5
//   plexus_test_peer sub --dds cyclone --domain 11 --count 5
//
// pub waits until every topic has a matched reader, publishes `count` patterned samples
// per type, then waits for the readers to go away (or linger time). sub exits 0 once it
// has received `count` intact samples of every type, 1 on timeout or corrupted data.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "message_pattern.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/participant.hpp"
#include "simple_values.hpp"

namespace {

using namespace plexus;

struct Endpoints {
  const msg::TypeSupport* ts;
  std::string topic;
  std::unique_ptr<rt::WriterBackend> writer;
  std::unique_ptr<rt::ReaderBackend> reader;
  std::vector<unsigned char> sample;  // storage for one T
  void* obj = nullptr;
  void (*destroy)(void*) = nullptr;
  int received = 0;
  int corrupted = 0;
  void (*fill)(const msg::TypeSupport&, void*, uint64_t) = nullptr;
  bool (*check)(const msg::TypeSupport&, void*) = nullptr;
};

// --values pattern: every type, a byte pattern. --values simple: Pose2D and JointState
// with the values the vendor-native peers use (simple_values.hpp).
void fill_pattern(const msg::TypeSupport& ts, void* obj, uint64_t seq) { plexus::test::fill_pattern(ts, obj, seq); }
bool check_pattern(const msg::TypeSupport& ts, void* obj) { return plexus::test::matches_pattern(ts, obj); }
template <class T>
void fill_simple(const msg::TypeSupport&, void* obj, uint64_t seq) {
  plexus::test::fill_simple(*static_cast<T*>(obj), seq);
}
template <class T>
bool check_simple(const msg::TypeSupport&, void* obj) {
  return plexus::test::check_simple(*static_cast<const T*>(obj));
}

template <class T>
void add(std::vector<Endpoints>& eps, const std::string& only, const std::string& prefix, bool simple) {
  const auto& ts = msg::type_support<T>();
  std::string short_name = std::string(ts.type_name).substr(std::string("plexus::msg::").size());
  if (!only.empty() && only != "all" && only != short_name) return;
  Endpoints e;
  if (simple) {
    if constexpr (std::is_same_v<T, msg::Pose2D> || std::is_same_v<T, msg::JointState>) {
      e.fill = &fill_simple<T>;
      e.check = &check_simple<T>;
    } else {
      return;
    }
  } else {
    e.fill = &fill_pattern;
    e.check = &check_pattern;
  }
  e.ts = &ts;
  e.topic = prefix + "/" + short_name;
  e.obj = new T();
  e.destroy = [](void* p) { delete static_cast<T*>(p); };
  eps.push_back(std::move(e));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"plexus test peer"};
  std::string role, dds = "fast", types = "all", prefix = "peer", values = "pattern", transport = "auto";
  int domain = 0, count = 5;
  double timeout_s = 20.0;
  app.add_option("role", role, "pub or sub")->required()->check(CLI::IsMember({"pub", "sub"}));
  app.add_option("--dds", dds, "fast or cyclone");
  app.add_option("--domain", domain, "DDS domain id");
  app.add_option("--count", count, "samples per type");
  app.add_option("--types", types, "all, or one type name (Pose2D)");
  app.add_option("--prefix", prefix, "topic prefix");
  app.add_option("--timeout", timeout_s, "seconds");
  app.add_option("--transport", transport, "auto, udp or shm");
  app.add_option("--values", values, "pattern (every type) or simple (Pose2D, JointState: native peers' values)")
      ->check(CLI::IsMember({"pattern", "simple"}));
  CLI11_PARSE(app, argc, argv);

  try {
    init_logging("peer-" + role + "-" + dds, "",
                 std::getenv("PLEXUS_LOG_LEVEL") ? std::getenv("PLEXUS_LOG_LEVEL") : "warn");
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = "plexus_test_peer " + role;
    po.network.transport = rt::parse_transport(transport);
    auto participant = rt::Participant::create(po);
    rt::QosProfile qos;
    qos.name = "test";
    qos.reliability = rt::QosProfile::Reliability::reliable;
    qos.history = rt::QosProfile::History::keep_last;
    qos.depth = count;
    // Transient-local: a reader that matches a moment after the writer (the writer sees the
    // match first, then writes before the reader side has discovered it) still gets every
    // sample. With volatile durability those samples are legitimately lost, and the test
    // would flake on a busy machine.
    qos.durability = rt::QosProfile::Durability::transient_local;

    std::vector<Endpoints> eps;
    std::apply([&](auto... t) { (add<decltype(t)>(eps, types, prefix, values == "simple"), ...); },
               msg::AllTopicTypes{});
    if (eps.empty()) throw InputError("--types: unknown type '" + types + "'");
    const int64_t deadline = monotonic_ns() + static_cast<int64_t>(timeout_s * 1e9);

    if (role == "pub") {
      for (auto& e : eps) e.writer = participant->make_writer(*e.ts, e.topic, qos);
      for (auto& e : eps)
        while (e.writer->matched_count() == 0) {
          if (monotonic_ns() > deadline) {
            std::fprintf(stderr, "pub: no reader matched on %s\n", e.topic.c_str());
            return 1;
          }
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      for (auto& e : eps)
        for (int k = 1; k <= count; ++k) {
          e.fill(*e.ts, e.obj, static_cast<uint64_t>(k));
          if (!e.writer->write(e.obj)) {
            std::fprintf(stderr, "pub: write failed on %s\n", e.topic.c_str());
            return 1;
          }
        }
      // Stay until the readers have gone (they leave once they have everything).
      for (auto& e : eps)
        while (e.writer->matched_count() > 0 && monotonic_ns() < deadline)
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
      std::printf("pub %s: published %d samples of %zu types\n", dds.c_str(), count, eps.size());
    } else {
      for (auto& e : eps) e.reader = participant->make_reader(*e.ts, e.topic, qos);
      bool done = false;
      while (!done && monotonic_ns() < deadline) {
        done = true;
        for (auto& e : eps) {
          while (e.reader->take(e.obj, nullptr)) {
            if (e.check(*e.ts, e.obj))
              ++e.received;
            else
              ++e.corrupted;
          }
          if (e.received < count) done = false;
        }
        if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      int bad = 0;
      for (auto& e : eps) {
        if (e.received < count || e.corrupted) {
          ++bad;
          std::fprintf(stderr, "sub: %s received %d/%d intact, %d corrupted\n", e.topic.c_str(), e.received, count,
                       e.corrupted);
        }
      }
      std::printf("sub %s: %zu types, %d incomplete\n", dds.c_str(), eps.size(), bad);
      for (auto& e : eps) e.destroy(e.obj);
      return bad == 0 ? 0 : 1;
    }
    for (auto& e : eps) e.destroy(e.obj);
  } catch (const InputError& e) {
    std::fprintf(stderr, "plexus_test_peer: error: %s\n", e.what());
    return kExitBadInput;
  }
  return 0;
}
