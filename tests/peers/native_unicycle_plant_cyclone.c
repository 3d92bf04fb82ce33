/* native_unicycle_plant_cyclone: a unicycle plant as a plain Cyclone DDS C program, built only
 * from the idlc output of plexus's IDL (no plexus code). Same behaviour, options and output
 * as native_unicycle_plant_fast.cpp.
 *
 *   native_unicycle_plant_cyclone --domain N [--robot r1] [--x0 0] [--y0 -6] [--theta0 0]
 *       [--rate 1000] [--sensor-rate 100] [--grid 0.1] [--duration 0]
 *
 *   in   <robot>/cmd          plexus::msg::UnicycleCommand  {v, omega}, latest held (zero before the first)
 *   out  <robot>/position     plexus::msg::PositionMeasurement  x, y on the RFID tag grid, z = 0, stddev = 0
 *        <robot>/truth/state  plexus::msg::Pose2D  exact x, y, theta (theta continuous, not wrapped)
 *
 * Integration: exact for a held command, at --rate on absolute CLOCK_MONOTONIC deadlines;
 * the sensor outputs at --sensor-rate on the same time line (the first at the start).
 * Every endpoint: reliable, keep-last 1, volatile, XCDR1. Network and discovery exactly as
 * native_cyclone_peer.c: loopback only, unicast discovery, no multicast. */
#define _POSIX_C_SOURCE 200809L
#include <dds/dds.h>
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "plexus/msg/pose.h"
#include "plexus/msg/wheel.h"

static const char* kConfig =
    "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>31</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
    "</Domain></CycloneDDS>";

#define PROG "native_unicycle_plant"

typedef struct {
  long domain;
  const char* robot;
  double x0, y0, theta0;
  double rate, sensor_rate, grid, duration;
} Options;

static volatile sig_atomic_t g_stop = 0;
static void on_signal(int sig) {
  (void)sig;
  g_stop = 1;
}

/* Latest command, written by the reader's data-available listener. */
typedef struct {
  pthread_mutex_t mu;
  double v, omega;
  uint64_t received;
} Command;

static int64_t clock_ns(clockid_t id) {
  struct timespec ts;
  clock_gettime(id, &ts);
  return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

static void usage(FILE* f) {
  fprintf(f,
          "usage: " PROG "_cyclone --domain N [--robot NAME] [--x0 X] [--y0 Y] [--theta0 TH] [--rate HZ]"
          " [--sensor-rate HZ] [--grid G] [--duration S]\n");
}

static int bad(const char* msg, const char* arg) {
  fprintf(stderr, PROG ": %s%s%s\n", msg, arg ? ": " : "", arg ? arg : "");
  return 2;
}

static int parse_double(const char* s, double* out) {
  char* end = NULL;
  errno = 0;
  const double v = strtod(s, &end);
  if (end == s || *end != '\0' || errno != 0 || !isfinite(v)) return 0;
  *out = v;
  return 1;
}

static int missing(const char* name) {
  fprintf(stderr, PROG ": missing value for %s\n", name);
  return 2;
}

/* Returns 0 when the options are fine, 1 for --help, 2 after printing an error. */
static int parse_options(int argc, char** argv, Options* o) {
  int have_domain = 0;
  o->domain = -1;
  o->robot = "r1";
  o->x0 = 0.0;
  o->y0 = -6.0;
  o->theta0 = 0.0;
  o->rate = 1000.0;
  o->sensor_rate = 100.0;
  o->grid = 0.1;
  o->duration = 0.0;
  for (int i = 1; i < argc; ++i) {
    const char* name = argv[i];
    const char* value = NULL;
    char buf[64];
    if (strcmp(name, "--help") == 0 || strcmp(name, "-h") == 0) return 1;
    if (strncmp(name, "--", 2) != 0) return bad("unexpected argument", name);
    const char* eq = strchr(name, '=');
    if (eq) { /* --name=value */
      const size_t n = (size_t)(eq - name);
      if (n >= sizeof buf) return bad("unknown option", name);
      memcpy(buf, name, n);
      buf[n] = '\0';
      name = buf;
      value = eq + 1;
    } else if (i + 1 < argc) {
      value = argv[++i];
    }
    double* target = NULL;
    if (strcmp(name, "--domain") == 0) {
      if (!value) return missing(name);
      char* end = NULL;
      errno = 0;
      const long d = strtol(value, &end, 10);
      if (end == value || *end != '\0' || errno != 0 || d < 0 || d > 232)
        return bad("--domain must be an integer in 0..232, got", value);
      o->domain = d;
      have_domain = 1;
      continue;
    } else if (strcmp(name, "--robot") == 0) {
      if (!value) return missing(name);
      if (value[0] == '\0') return bad("--robot must not be empty", NULL);
      o->robot = value;
      continue;
    } else if (strcmp(name, "--x0") == 0) {
      target = &o->x0;
    } else if (strcmp(name, "--y0") == 0) {
      target = &o->y0;
    } else if (strcmp(name, "--theta0") == 0) {
      target = &o->theta0;
    } else if (strcmp(name, "--rate") == 0) {
      target = &o->rate;
    } else if (strcmp(name, "--sensor-rate") == 0) {
      target = &o->sensor_rate;
    } else if (strcmp(name, "--grid") == 0) {
      target = &o->grid;
    } else if (strcmp(name, "--duration") == 0) {
      target = &o->duration;
    } else {
      return bad("unknown option", name);
    }
    if (!value) return missing(name);
    if (!parse_double(value, target)) {
      fprintf(stderr, PROG ": %s expects a finite number, got: %s\n", name, value);
      return 2;
    }
  }
  if (!have_domain) return bad("--domain is required", NULL);
  if (!(o->rate > 0.0) || o->rate > 1e6) return bad("--rate must be in (0, 1e6] Hz", NULL);
  if (!(o->sensor_rate > 0.0)) return bad("--sensor-rate must be > 0", NULL);
  if (o->sensor_rate > o->rate) return bad("--sensor-rate must not exceed --rate", NULL);
  if (!(o->grid > 0.0)) return bad("--grid must be > 0", NULL);
  if (o->duration < 0.0) return bad("--duration must be >= 0", NULL);
  if (strlen(o->robot) > 200) return bad("--robot is too long", NULL);
  return 0;
}

static void on_command(dds_entity_t reader, void* arg) {
  Command* c = (Command*)arg;
  plexus_msg_UnicycleCommand m;
  void* ptr = &m;
  dds_sample_info_t info;
  while (dds_take(reader, &ptr, &info, 1, 1) > 0) {
    if (!info.valid_data || !isfinite(m.v) || !isfinite(m.omega)) continue; /* non-finite: ignored */
    pthread_mutex_lock(&c->mu);
    c->v = m.v;
    c->omega = m.omega;
    ++c->received;
    pthread_mutex_unlock(&c->mu);
  }
}

/* Nearest tag of the grid; +0.0 turns a -0.0 into 0. */
static double on_grid(double x, double g) { return round(x / g) * g + 0.0; }

int main(int argc, char** argv) {
  Options o;
  const int prc = parse_options(argc, argv, &o);
  if (prc == 1) {
    usage(stdout);
    return 0;
  }
  if (prc != 0) return 2;

  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);

  char tcmd[256], tpos[256], ttruth[256];
  snprintf(tcmd, sizeof tcmd, "%s/cmd", o.robot);
  snprintf(tpos, sizeof tpos, "%s/position", o.robot);
  snprintf(ttruth, sizeof ttruth, "%s/truth/state", o.robot);

  const dds_domainid_t domain = (dds_domainid_t)o.domain;
  dds_create_domain(domain, kConfig);
  dds_qos_t* pq = dds_create_qos();
  dds_qset_entity_name(pq, "native_unicycle_plant_cyclone");
  const dds_entity_t pp = dds_create_participant(domain, pq, NULL);
  dds_delete_qos(pq);
  if (pp < 0) {
    fprintf(stderr, PROG ": cannot create participant on domain %ld: %s\n", o.domain, dds_strretcode(pp));
    return 1;
  }
  const dds_entity_t t_cmd = dds_create_topic(pp, &plexus_msg_UnicycleCommand_desc, tcmd, NULL, NULL);
  const dds_entity_t t_pos = dds_create_topic(pp, &plexus_msg_PositionMeasurement_desc, tpos, NULL, NULL);
  const dds_entity_t t_truth = dds_create_topic(pp, &plexus_msg_Pose2D_desc, ttruth, NULL, NULL);
  if (t_cmd < 0 || t_pos < 0 || t_truth < 0) {
    fprintf(stderr, PROG ": cannot create topics\n");
    dds_delete(pp);
    return 1;
  }
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(q, DDS_DURABILITY_VOLATILE);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q, 1, &xcdr1);

  Command cmd;
  pthread_mutex_init(&cmd.mu, NULL);
  cmd.v = 0.0;
  cmd.omega = 0.0;
  cmd.received = 0;
  dds_listener_t* listener = dds_create_listener(&cmd);
  dds_lset_data_available(listener, on_command);
  const dds_entity_t w_pos = dds_create_writer(pp, t_pos, q, NULL);
  const dds_entity_t w_truth = dds_create_writer(pp, t_truth, q, NULL);
  const dds_entity_t r_cmd = dds_create_reader(pp, t_cmd, q, listener);
  dds_delete_qos(q);
  if (w_pos < 0 || w_truth < 0 || r_cmd < 0) {
    fprintf(stderr, PROG ": cannot create endpoints\n");
    dds_delete(pp);
    dds_delete_listener(listener);
    return 1;
  }

  /* Step k ends at t0 + k / rate; sensor sample j is due at t0 + j / sensor_rate and is
     published at the first step ending at or after that time. */
  const double h = 1.0 / o.rate;
  const int64_t last_step = o.duration > 0.0 ? (int64_t)llround(o.duration * o.rate) : INT64_MAX;
  double x = o.x0, y = o.y0, theta = o.theta0;
  uint64_t seq_pos = 0, seq_truth = 0;
  int64_t k = 0, j = 0;
  const int64_t t0 = clock_ns(CLOCK_MONOTONIC);
  int rc = 0;
  while (!g_stop) {
    const int64_t step_off = (int64_t)llround((double)k * 1e9 / o.rate);
    if (step_off >= (int64_t)llround((double)j * 1e9 / o.sensor_rate)) {
      const int64_t now = clock_ns(CLOCK_REALTIME);
      plexus_msg_PositionMeasurement pm;
      memset(&pm, 0, sizeof pm);
      pm.header.seq_num = ++seq_pos;
      pm.header.data_time_ns = now;
      pm.header.origin_time_ns = now;
      pm.x = on_grid(x, o.grid);
      pm.y = on_grid(y, o.grid);
      pm.z = 0.0;
      pm.stddev = 0.0;
      plexus_msg_Pose2D tp;
      memset(&tp, 0, sizeof tp);
      tp.header.seq_num = ++seq_truth;
      tp.header.data_time_ns = now;
      tp.header.origin_time_ns = now;
      tp.x = x;
      tp.y = y;
      tp.theta = theta;
      pm.header.publish_time_ns = clock_ns(CLOCK_REALTIME);
      if (dds_write(w_pos, &pm) < 0) rc = 1;
      tp.header.publish_time_ns = clock_ns(CLOCK_REALTIME);
      if (dds_write(w_truth, &tp) < 0) rc = 1;
      while (step_off >= (int64_t)llround((double)j * 1e9 / o.sensor_rate)) ++j;
    }
    if (k >= last_step) break;

    const int64_t deadline = t0 + (int64_t)llround((double)(k + 1) * 1e9 / o.rate);
    struct timespec ts = {(time_t)(deadline / 1000000000LL), (long)(deadline % 1000000000LL)};
    int err;
    while ((err = clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL)) == EINTR && !g_stop) {
    }
    if (g_stop) break;

    pthread_mutex_lock(&cmd.mu);
    const double v = cmd.v, w = cmd.omega;
    pthread_mutex_unlock(&cmd.mu);
    if (fabs(w) > 1e-9) {
      const double th1 = theta + w * h;
      x += v / w * (sin(th1) - sin(theta));
      y += -v / w * (cos(th1) - cos(theta));
    } else {
      x += v * h * cos(theta);
      y += v * h * sin(theta);
    }
    theta += w * h;
    ++k;
  }

  /* Stop receiving before reading the count: no callback runs after the reader is gone. */
  dds_delete(r_cmd);
  pthread_mutex_lock(&cmd.mu);
  const uint64_t received = cmd.received;
  pthread_mutex_unlock(&cmd.mu);
  printf(PROG ": %lld steps, %llu commands received, final pose %.6f %.6f %.6f\n", (long long)k,
         (unsigned long long)received, x, y, theta);
  fflush(stdout);
  dds_delete(pp);
  dds_delete_listener(listener);
  pthread_mutex_destroy(&cmd.mu);
  if (rc != 0) fprintf(stderr, PROG ": some writes failed\n");
  return 0;
}
