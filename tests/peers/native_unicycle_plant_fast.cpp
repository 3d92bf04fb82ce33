// native_unicycle_plant_fast: a unicycle plant as a plain Fast DDS 2.9 program, built only
// from the fastddsgen types of plexus's IDL (no plexus code). Same behaviour, options and
// output as native_unicycle_plant_cyclone.c.
//
//   native_unicycle_plant_fast --domain N [--robot r1] [--x0 0] [--y0 -6] [--theta0 0]
//       [--rate 1000] [--sensor-rate 100] [--grid 0.1] [--duration 0]
//
//   in   <robot>/cmd          plexus::msg::UnicycleCommand  {v, omega}, latest held (zero before the first)
//   out  <robot>/position     plexus::msg::PositionMeasurement  x, y on the RFID tag grid, z = 0, stddev = 0
//        <robot>/truth/state  plexus::msg::Pose2D  exact x, y, theta (theta continuous, not wrapped)
//
// Integration: exact for a held command, at --rate on absolute CLOCK_MONOTONIC deadlines;
// the sensor outputs at --sensor-rate on the same time line (the first at the start).
// Every endpoint: reliable, keep-last 1, volatile, no data sharing, XCDR1. Network and
// discovery exactly as native_fast_peer.cpp: UDPv4 on 127.0.0.1 only (no shared memory),
// unicast discovery to the 32 well-known ports of the domain, no multicast.
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <mutex>
#include <string>

#include "posePubSubTypes.h"
#include "wheelPubSubTypes.h"

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;

namespace {

constexpr const char* kProg = "native_unicycle_plant";

struct Options {
  long domain = -1;
  std::string robot = "r1";
  double x0 = 0.0, y0 = -6.0, theta0 = 0.0;
  double rate = 1000.0, sensor_rate = 100.0, grid = 0.1, duration = 0.0;
};

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_signal(int) { g_stop = 1; }

int64_t clock_ns(clockid_t id) {
  timespec ts{};
  clock_gettime(id, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1'000'000'000LL + ts.tv_nsec;
}

void usage(std::FILE* f) {
  std::fprintf(f,
               "usage: native_unicycle_plant_fast --domain N [--robot NAME] [--x0 X] [--y0 Y] [--theta0 TH]"
               " [--rate HZ] [--sensor-rate HZ] [--grid G] [--duration S]\n");
}

int bad(const std::string& msg) {
  std::fprintf(stderr, "%s: %s\n", kProg, msg.c_str());
  return 2;
}

bool parse_double(const char* s, double& out) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (end == s || *end != '\0' || errno != 0 || !std::isfinite(v)) return false;
  out = v;
  return true;
}

// 0 when the options are fine, 1 for --help, 2 after printing an error.
int parse_options(int argc, char** argv, Options& o) {
  bool have_domain = false;
  for (int i = 1; i < argc; ++i) {
    std::string name = argv[i];
    const char* value = nullptr;
    if (name == "--help" || name == "-h") return 1;
    if (name.rfind("--", 0) != 0) return bad("unexpected argument: " + name);
    const auto eq = name.find('=');
    if (eq != std::string::npos) {  // --name=value
      value = argv[i] + eq + 1;
      name.resize(eq);
    } else if (i + 1 < argc) {
      value = argv[++i];
    }
    double* target = nullptr;
    if (name == "--domain") {
      if (!value) return bad("missing value for " + name);
      char* end = nullptr;
      errno = 0;
      const long d = std::strtol(value, &end, 10);
      if (end == value || *end != '\0' || errno != 0 || d < 0 || d > 232)
        return bad(std::string("--domain must be an integer in 0..232, got: ") + value);
      o.domain = d;
      have_domain = true;
      continue;
    } else if (name == "--robot") {
      if (!value) return bad("missing value for " + name);
      if (value[0] == '\0') return bad("--robot must not be empty");
      o.robot = value;
      continue;
    } else if (name == "--x0") {
      target = &o.x0;
    } else if (name == "--y0") {
      target = &o.y0;
    } else if (name == "--theta0") {
      target = &o.theta0;
    } else if (name == "--rate") {
      target = &o.rate;
    } else if (name == "--sensor-rate") {
      target = &o.sensor_rate;
    } else if (name == "--grid") {
      target = &o.grid;
    } else if (name == "--duration") {
      target = &o.duration;
    } else {
      return bad("unknown option: " + name);
    }
    if (!value) return bad("missing value for " + name);
    if (!parse_double(value, *target)) return bad(name + " expects a finite number, got: " + value);
  }
  if (!have_domain) return bad("--domain is required");
  if (!(o.rate > 0.0) || o.rate > 1e6) return bad("--rate must be in (0, 1e6] Hz");
  if (!(o.sensor_rate > 0.0)) return bad("--sensor-rate must be > 0");
  if (o.sensor_rate > o.rate) return bad("--sensor-rate must not exceed --rate");
  if (!(o.grid > 0.0)) return bad("--grid must be > 0");
  if (o.duration < 0.0) return bad("--duration must be >= 0");
  if (o.robot.size() > 200) return bad("--robot is too long");
  return 0;
}

// Latest command, written from the reader's on_data_available (a Fast DDS thread).
class CommandListener final : public DataReaderListener {
 public:
  void on_data_available(DataReader* reader) override {
    plexus::msg::UnicycleCommand m;
    SampleInfo info;
    while (reader->take_next_sample(&m, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data || !std::isfinite(m.v()) || !std::isfinite(m.omega())) continue;  // non-finite: ignored
      std::lock_guard<std::mutex> lock(mu_);
      v_ = m.v();
      omega_ = m.omega();
      ++received_;
    }
  }
  void get(double& v, double& omega) {
    std::lock_guard<std::mutex> lock(mu_);
    v = v_;
    omega = omega_;
  }
  uint64_t received() {
    std::lock_guard<std::mutex> lock(mu_);
    return received_;
  }

 private:
  std::mutex mu_;
  double v_ = 0.0, omega_ = 0.0;
  uint64_t received_ = 0;
};

// Nearest tag of the grid; + 0.0 turns a -0.0 into 0.
double on_grid(double x, double g) { return std::round(x / g) * g + 0.0; }

}  // namespace

int main(int argc, char** argv) {
  Options o;
  const int prc = parse_options(argc, argv, o);
  if (prc == 1) {
    usage(stdout);
    return 0;
  }
  if (prc != 0) return 2;

  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);

  const int domain = static_cast<int>(o.domain);
  DomainParticipantQos pq;
  pq.name("native_unicycle_plant_fast");
  pq.transport().use_builtin_transports = false;
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.push_back("127.0.0.1");
  pq.transport().user_transports.push_back(udp);
  pq.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(Locator_t());
  for (int pid = 0; pid < 32; ++pid) {
    Locator_t loc;
    IPLocator::setIPv4(loc, "127.0.0.1");
    loc.port = static_cast<uint32_t>(7400 + 250 * domain + 10 + 2 * pid);
    pq.wire_protocol().builtin.initialPeersList.push_back(loc);
  }
  auto* factory = DomainParticipantFactory::get_instance();
  DomainParticipant* dp = factory->create_participant(domain, pq);
  if (!dp) {
    std::fprintf(stderr, "%s: cannot create participant on domain %d\n", kProg, domain);
    return 1;
  }
  TypeSupport cmd_type(new plexus::msg::UnicycleCommandPubSubType());
  TypeSupport pos_type(new plexus::msg::PositionMeasurementPubSubType());
  TypeSupport pose_type(new plexus::msg::Pose2DPubSubType());
  cmd_type.register_type(dp);
  pos_type.register_type(dp);
  pose_type.register_type(dp);
  Topic* t_cmd = dp->create_topic(o.robot + "/cmd", cmd_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Topic* t_pos = dp->create_topic(o.robot + "/position", pos_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Topic* t_truth = dp->create_topic(o.robot + "/truth/state", pose_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Publisher* pub = dp->create_publisher(PUBLISHER_QOS_DEFAULT);
  Subscriber* sub = dp->create_subscriber(SUBSCRIBER_QOS_DEFAULT);

  DataWriterQos wq = DATAWRITER_QOS_DEFAULT;
  wq.reliability().kind = RELIABLE_RELIABILITY_QOS;
  wq.history().kind = KEEP_LAST_HISTORY_QOS;
  wq.history().depth = 1;
  wq.durability().kind = VOLATILE_DURABILITY_QOS;
  wq.data_sharing().off();
  wq.representation().m_value.clear();
  wq.representation().m_value.push_back(XCDR_DATA_REPRESENTATION);
  DataReaderQos rq = DATAREADER_QOS_DEFAULT;
  rq.reliability().kind = RELIABLE_RELIABILITY_QOS;
  rq.history().kind = KEEP_LAST_HISTORY_QOS;
  rq.history().depth = 1;
  rq.durability().kind = VOLATILE_DURABILITY_QOS;
  rq.data_sharing().off();
  rq.type_consistency().representation.m_value.clear();
  rq.type_consistency().representation.m_value.push_back(XCDR_DATA_REPRESENTATION);

  CommandListener listener;
  DataWriter* w_pos = (t_pos && pub) ? pub->create_datawriter(t_pos, wq) : nullptr;
  DataWriter* w_truth = (t_truth && pub) ? pub->create_datawriter(t_truth, wq) : nullptr;
  DataReader* r_cmd =
      (t_cmd && sub) ? sub->create_datareader(t_cmd, rq, &listener, StatusMask::data_available()) : nullptr;
  if (!w_pos || !w_truth || !r_cmd) {
    std::fprintf(stderr, "%s: cannot create endpoints\n", kProg);
    if (r_cmd) r_cmd->set_listener(nullptr);
    dp->delete_contained_entities();
    factory->delete_participant(dp);
    return 1;
  }

  // Step k ends at t0 + k / rate; sensor sample j is due at t0 + j / sensor_rate and is
  // published at the first step ending at or after that time.
  const double h = 1.0 / o.rate;
  const int64_t last_step = o.duration > 0.0 ? static_cast<int64_t>(std::llround(o.duration * o.rate)) : INT64_MAX;
  const auto step_offset = [&](int64_t k) {
    return static_cast<int64_t>(std::llround(static_cast<double>(k) * 1e9 / o.rate));
  };
  const auto sensor_offset = [&](int64_t j) {
    return static_cast<int64_t>(std::llround(static_cast<double>(j) * 1e9 / o.sensor_rate));
  };
  double x = o.x0, y = o.y0, theta = o.theta0;
  uint64_t seq_pos = 0, seq_truth = 0;
  int64_t k = 0, j = 0;
  bool write_failed = false;
  plexus::msg::PositionMeasurement pm;
  plexus::msg::Pose2D tp;
  const int64_t t0 = clock_ns(CLOCK_MONOTONIC);
  while (!g_stop) {
    const int64_t step_off = step_offset(k);
    if (step_off >= sensor_offset(j)) {
      const int64_t now = clock_ns(CLOCK_REALTIME);
      pm.header().seq_num(++seq_pos);
      pm.header().data_time_ns(now);
      pm.header().origin_time_ns(now);
      pm.x(on_grid(x, o.grid));
      pm.y(on_grid(y, o.grid));
      pm.z(0.0);
      pm.stddev(0.0);
      tp.header().seq_num(++seq_truth);
      tp.header().data_time_ns(now);
      tp.header().origin_time_ns(now);
      tp.x(x);
      tp.y(y);
      tp.theta(theta);
      pm.header().publish_time_ns(clock_ns(CLOCK_REALTIME));
      if (!w_pos->write(&pm)) write_failed = true;
      tp.header().publish_time_ns(clock_ns(CLOCK_REALTIME));
      if (!w_truth->write(&tp)) write_failed = true;
      while (step_off >= sensor_offset(j)) ++j;
    }
    if (k >= last_step) break;

    const int64_t deadline = t0 + step_offset(k + 1);
    const timespec ts{static_cast<time_t>(deadline / 1'000'000'000LL), static_cast<long>(deadline % 1'000'000'000LL)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR && !g_stop) {}
    if (g_stop) break;

    double v = 0.0, w = 0.0;
    listener.get(v, w);
    if (std::fabs(w) > 1e-9) {
      const double th1 = theta + w * h;
      x += v / w * (std::sin(th1) - std::sin(theta));
      y += -v / w * (std::cos(th1) - std::cos(theta));
    } else {
      x += v * h * std::cos(theta);
      y += v * h * std::sin(theta);
    }
    theta += w * h;
    ++k;
  }

  // Stop receiving before reading the count.
  r_cmd->set_listener(nullptr);
  sub->delete_datareader(r_cmd);
  std::printf("%s: %lld steps, %llu commands received, final pose %.6f %.6f %.6f\n", kProg, static_cast<long long>(k),
              static_cast<unsigned long long>(listener.received()), x, y, theta);
  std::fflush(stdout);
  dp->delete_contained_entities();
  factory->delete_participant(dp);
  if (write_failed) std::fprintf(stderr, "%s: some writes failed\n", kProg);
  return 0;
}
