// table4_fit: fits the set-up paper 004 leaves unstated to both columns of its Table 4 at
// once (issue 29; docs/algorithms/arm.md "Table 4: the set-up").
//
// Table 4 gives 14 figures for two controllers (VDC+EKF and CT+PD) run on one set-up. The
// paper states the arm (Tables 1-2), the reference (59), the gains (Table 3, (60)) and the
// observer's Q, R, P(0); it does not state the run length T, the initial state, the gravity
// direction, the reference point of I_O, the integration step, or how the observer starts,
// and (60) allows several readings. This tool runs the closed loop of plexus's own
// algorithms (the plant, encoders, EKF and controllers the scenarios run, in the scenario
// runner's order: plant step with the last command, sample, observer update, control) for
// every combination of the candidate values given on the command line, in parallel, and
// ranks each (set-up, VDC reading, CT+PD reading, T) by its worst relative error over the
// 14 figures. T is not simulated separately: the metrics of every T in --times come from
// one run (a T past the run's end extends the last two periods' mean-square error, marked),
// and a settling time counts only if the error stays in the band for --hold (1 s) after it.
//
//   table4_fit --gravity hanging,none --inertia joint,com --q0 0,0.5 --dq0 0,1 --jobs 2
//
// Prints the best rows and writes every row to --csv. Exit 2 on a bad argument.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <mutex>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include "plexus/algorithms/arm/chain_dynamics.hpp"
#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/sine_reference.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/base/comma_list.hpp"

namespace alg = plexus::algorithms;

namespace {

constexpr double kBand = 1.15e-3;  // rad: Table 4's settling band
constexpr int kFigures = 14;
// Table 4 (RMS in mrad, docs/algorithms/arm.md): e1, e2, |e|, settling 1, 2, peak 1, 2;
// VDC+EKF first, then CT+PD.
constexpr double kPaper[kFigures] = {0.649, 0.619, 0.900, 0.36, 0.37, 46.33, 14.39,
                                     2.20,  1.60,  2.72,  1.30, 1.34, 66.20, 19.64};
const char* const kFigureNames[kFigures] = {"vdc_rms1", "vdc_rms2", "vdc_rms", "vdc_set1", "vdc_set2",
                                            "vdc_max1", "vdc_max2", "ct_rms1", "ct_rms2",  "ct_rms",
                                            "ct_set1",  "ct_set2",  "ct_max1", "ct_max2"};

// One set-up: what both controllers share.
struct SetUp {
  std::string gravity;   // hanging (q = 0 hangs), none (horizontal plane), side, side-, upright
  std::string inertia;   // joint: I_O about the joint axis; com: about the centre of mass
  double q0 = 0.0;       // q(0) as a fraction of q_d(0) (0: q(0) = 0, 1: on the reference)
  double dq0 = 0.0;      // rad/s: q'(0) = phi'(0)
  double step = 2e-4;    // s: controller and observer period
  std::string ekf_init;  // steady: x^(0) holds C q' + G (the scenarios); zero: tau^(0) = 0;
                         // origin: x^(0) = 0 (a simulation's default); a number a: tau^(0) = a (C q' + G)
  double limit1 = 0.0;   // N m: drive torque limit of joint 1 (joint 2 scaled by 19.64/66.20); 0: none
};

struct Reading {
  std::string controller;  // vdc | ctpd
  std::string name;        // e.g. "model@1", "motor/links/desired"
  alg::LinkAcceleration acceleration = alg::LinkAcceleration::kModel;
  double theta_initial = 1.0;  // VDC: theta^(0) as a fraction of the true parameters
  double accel_hz = 50.0;
  alg::CtPdVelocity velocity = alg::CtPdVelocity::kMotor;
  alg::CtPdInertia inertia = alg::CtPdInertia::kLinks;
  alg::CtPdAcceleration ct_acceleration = alg::CtPdAcceleration::kDesired;
};

// Per-step record of one run.
struct Trace {
  std::vector<double> e1, e2, u1, u2;  // rad, N m
  bool diverged = false;
};

struct Figures {
  double f[7];        // rms1, rms2, rms (mrad), settling 1, 2 (s, inf: never), peak 1, 2 (N m)
  bool extrapolated;  // T beyond the simulated duration
};

alg::ArmModel model_of(const SetUp& s) {
  alg::ArmModel m = alg::ArmModel::paper_2dof();
  constexpr double g = 9.81;
  if (s.gravity == "hanging")
    m.gravity = {g, 0, 0};
  else if (s.gravity == "none")
    m.gravity = {0, 0, 0};
  else if (s.gravity == "side")
    m.gravity = {0, g, 0};
  else if (s.gravity == "side-")
    m.gravity = {0, -g, 0};
  else if (s.gravity == "upright")
    m.gravity = {-g, 0, 0};
  if (s.inertia == "com")
    for (alg::ArmLink& l : m.links) l.inertia_o += l.mass * l.com * l.com;
  return m;
}

Trace simulate(const SetUp& s, const Reading& r, double duration, std::uint64_t seed) {
  const alg::ArmModel model = model_of(s);
  const int n = 2;
  alg::FlexibleJointArmParams pp{model, 1e-4, {}};
  Eigen::VectorXd limit;
  if (s.limit1 > 0.0) {
    limit = Eigen::Vector2d(s.limit1, s.limit1 * 19.64 / 66.20);
    pp.torque_limit = limit;
  }
  alg::FlexibleJointArmPlant plant(pp);
  const alg::ArmSineReference reference(alg::ArmSineReferenceParams::paper(n));
  alg::ArmReferenceSample ref;
  reference.sample(0.0, ref);
  plant.reset_in_motion(s.q0 * ref.q, Eigen::VectorXd::Constant(n, s.dq0));

  alg::FlexibleJointEkfParams ep = alg::FlexibleJointEkfParams::paper();
  ep.model = model;
  ep.step = s.step;
  ep.acceleration = r.acceleration;
  ep.accel_filter_hz = r.accel_hz;
  alg::FlexibleJointEkf ekf(ep);

  alg::VdcParams vp = alg::VdcParams::paper_2dof();
  vp.model = model;
  vp.step = s.step;
  vp.torque_limit = limit;
  vp.theta_initial = r.theta_initial;
  alg::CtPdParams cp = alg::CtPdParams::paper_2dof();
  cp.model = model;
  cp.velocity = r.velocity;
  cp.inertia = r.inertia;
  cp.acceleration = r.ct_acceleration;
  const bool vdc = r.controller == "vdc";
  std::unique_ptr<alg::VdcController> vdc_ctrl;
  std::unique_ptr<alg::CtPdController> ct_ctrl;
  if (vdc)
    vdc_ctrl = std::make_unique<alg::VdcController>(vp);
  else
    ct_ctrl = std::make_unique<alg::CtPdController>(cp);

  // The encoders of the scenarios: sigma_phi 1e-5 rad, sigma_phi' 1e-3 rad/s.
  alg::Rng rng(seed);
  Eigen::VectorXd y(2 * n), u = Eigen::VectorXd::Zero(n);
  auto sample = [&] {
    const alg::FlexibleJointArmState& x = plant.state();
    for (int i = 0; i < n; ++i) y(i) = x.phi(i) + 1e-5 * rng.normal();
    for (int i = 0; i < n; ++i) y(n + i) = x.phid(i) + 1e-3 * rng.normal();
  };
  sample();
  {  // the observer's start (arm_ekf's first step): steady motion, or no torque
    alg::ArmChainDynamics dyn(model);
    Eigen::VectorXd g(n), x0(4 * n);
    dyn.inverse_dynamics(y.head(n), y.tail(n), Eigen::VectorXd::Zero(n), g);
    if (s.ekf_init == "zero")
      g.setZero();
    else if (s.ekf_init != "steady" && s.ekf_init != "origin")
      g *= std::stod(s.ekf_init);
    x0 << g, Eigen::VectorXd::Zero(n), y;
    if (s.ekf_init == "origin") x0.setZero();
    ekf.reset(x0);
  }
  const auto steps = static_cast<long>(std::llround(duration / s.step));
  Trace t;
  for (auto* v : {&t.e1, &t.e2, &t.u1, &t.u2}) v->reserve(static_cast<std::size_t>(steps + 1));
  for (long k = 0; k <= steps; ++k) {
    if (k > 0) {
      plant.step(u, s.step);
      sample();
      ekf.update(u, y, s.step);
    }
    reference.sample(static_cast<double>(k) * s.step, ref);
    u = vdc ? vdc_ctrl->step(ref, ekf.feedback()) : ct_ctrl->step(ref, ekf.feedback());
    const alg::FlexibleJointArmState& x = plant.state();
    t.e1.push_back(x.q(0) - ref.q(0));
    t.e2.push_back(x.q(1) - ref.q(1));
    t.u1.push_back(std::abs(u(0)));
    t.u2.push_back(std::abs(u(1)));
    if (!u.allFinite() || !x.q.allFinite() || u.cwiseAbs().maxCoeff() > 1e6) {
      t.diverged = true;
      break;
    }
  }
  return t;
}

// The Table 4 metrics of a trace over [0, T] (the scenario metrics' definitions:
// tracking_rms, settling_time, value_max_abs of the command), except that a settling time
// counts only if the error then stays in the band for `hold` seconds of the window: one at
// the window's end is an artefact (the error leaves the band again after it).
Figures figures(const Trace& t, double step, double T, double hold) {
  Figures out{};
  const double inf = std::numeric_limits<double>::infinity();
  if (t.diverged) {
    for (double& f : out.f) f = inf;
    return out;
  }
  const auto have = t.e1.size();
  const auto want = static_cast<std::size_t>(std::llround(T / step)) + 1;
  const std::size_t m = std::min(have, want);
  out.extrapolated = want > have;
  double s1 = 0, s2 = 0, p1 = 0, p2 = 0;
  long last1 = -1, last2 = -1;
  for (std::size_t k = 0; k < m; ++k) {
    s1 += t.e1[k] * t.e1[k], s2 += t.e2[k] * t.e2[k];
    p1 = std::max(p1, t.u1[k]), p2 = std::max(p2, t.u2[k]);
    if (std::abs(t.e1[k]) > kBand) last1 = static_cast<long>(k);
    if (std::abs(t.e2[k]) > kBand) last2 = static_cast<long>(k);
  }
  double count = static_cast<double>(m);
  if (out.extrapolated) {  // steady state: the last two reference periods' mean square
    const auto tail = std::min(have, static_cast<std::size_t>(std::llround(2.0 / step)));
    double m1 = 0, m2 = 0;
    for (std::size_t k = have - tail; k < have; ++k) m1 += t.e1[k] * t.e1[k], m2 += t.e2[k] * t.e2[k];
    const double extra = static_cast<double>(want - have);
    s1 += extra * m1 / static_cast<double>(tail), s2 += extra * m2 / static_cast<double>(tail);
    count = static_cast<double>(want);
  }
  out.f[0] = 1e3 * std::sqrt(s1 / count);
  out.f[1] = 1e3 * std::sqrt(s2 / count);
  out.f[2] = 1e3 * std::sqrt((s1 + s2) / count);
  auto settle = [&](long last) {
    const double s = last < 0 ? 0.0 : static_cast<double>(last + 1) * step;
    return s > T - hold ? inf : s;  // ends outside the band, or not long enough inside
  };
  out.f[3] = settle(last1);
  out.f[4] = settle(last2);
  out.f[5] = p1;
  out.f[6] = p2;
  return out;
}

std::vector<double> numbers(const std::string& what, const std::string& s) {
  std::vector<double> v;
  for (const std::string& x : plexus::split_comma_list(s)) {
    std::size_t used = 0;
    double d = 0;
    try {
      d = std::stod(x, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != x.size() || !std::isfinite(d)) throw CLI::ValidationError(what, "not a number: " + x);
    v.push_back(d);
  }
  if (v.empty()) throw CLI::ValidationError(what, "empty list");
  return v;
}

std::vector<std::string> words(const std::string& what, const std::string& s, const std::vector<std::string>& allowed) {
  std::vector<std::string> v = plexus::split_comma_list(s);
  for (const std::string& x : v)
    if (std::find(allowed.begin(), allowed.end(), x) == allowed.end())
      throw CLI::ValidationError(what, "unknown value " + x);
  if (v.empty()) throw CLI::ValidationError(what, "empty list");
  return v;
}

std::vector<Reading> vdc_readings(const std::vector<std::string>& accel, const std::vector<double>& theta) {
  std::vector<Reading> v;
  for (const std::string& a : accel)
    for (double th : theta) {
      Reading r;
      r.controller = "vdc";
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s@%g", a.c_str(), th);
      r.name = buf;
      r.theta_initial = th;
      if (a != "model") {
        r.acceleration = alg::LinkAcceleration::kDifferentiator;
        r.accel_hz = std::stod(a.substr(4));  // "diff<hz>"
      }
      v.push_back(r);
    }
  return v;
}

std::vector<Reading> ct_readings(const std::vector<std::string>& vel, const std::vector<std::string>& inertia,
                                 const std::vector<std::string>& accel) {
  std::vector<Reading> v;
  for (const std::string& a : vel)
    for (const std::string& b : inertia)
      for (const std::string& c : accel) {
        Reading r;
        r.controller = "ctpd";
        r.name = a + "/" + b + "/" + c;
        r.velocity = a == "link" ? alg::CtPdVelocity::kLink : alg::CtPdVelocity::kMotor;
        r.inertia = b == "links" ? alg::CtPdInertia::kLinks : alg::CtPdInertia::kWithMotors;
        r.ct_acceleration = c == "desired" ? alg::CtPdAcceleration::kDesired : alg::CtPdAcceleration::kEstimated;
        v.push_back(r);
      }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"table4_fit: fit paper 004's unstated set-up to both columns of Table 4 (issue 29)"};
  app.set_version_flag("--version", std::string("table4_fit ") + PLEXUS_VERSION);
  std::string gravity = "hanging", inertia = "joint", q0 = "0", dq0 = "1", step = "0.0002", ekf_init = "steady",
              limit = "0", vdc_accel = "model", ct_vel = "motor", ct_inertia = "links", ct_accel = "desired",
              theta = "1", times = "5", csv;
  double duration = 6.0, hold = 1.0;
  int jobs = 2, top = 15;
  std::uint64_t seed = 4;
  app.add_option("--gravity", gravity, "hanging, none, side, side-, upright (comma list)");
  app.add_option("--inertia", inertia, "I_O about the joint or the centre of mass: joint, com");
  app.add_option("--q0", q0, "q(0) as a fraction of q_d(0)");
  app.add_option("--dq0", dq0, "q'(0) = phi'(0), rad/s");
  app.add_option("--step", step, "controller period, s");
  app.add_option("--ekf-init", ekf_init,
                 "the observer's x^(0): steady, zero, origin, or a fraction of the steady torque");
  app.add_option("--limit", limit, "drive torque limit of joint 1, N m (joint 2 scaled); 0: none");
  app.add_option("--vdc-accel", vdc_accel, "the observer's q'' for VDC: model, diff<hz>");
  app.add_option("--vdc-theta", theta, "VDC's theta^(0), fraction of the true parameters, in [0.6, 1.8]");
  app.add_option("--ct-velocity", ct_vel, "K_v term of (60): motor, link");
  app.add_option("--ct-inertia", ct_inertia, "computed-torque inertia of (60): links, motors");
  app.add_option("--ct-accel", ct_accel, "acceleration of (60): desired, estimated");
  app.add_option("--times", times, "run lengths T to score, s");
  app.add_option("--duration", duration, "simulated duration per run, s")->check(CLI::Range(1.0, 60.0));
  app.add_option("--hold", hold, "s: a settling time counts if the error then stays in the band this long")
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--jobs", jobs, "parallel runs")->check(CLI::Range(1, 64));
  app.add_option("--top", top, "rows to print")->check(CLI::Range(1, 100000));
  app.add_option("--seed", seed, "encoder noise seed");
  app.add_option("--csv", csv, "write every row here");

  std::vector<SetUp> setups;
  std::vector<Reading> readings;
  std::vector<double> ts;
  try {
    app.parse(argc, argv);
    for (const std::string& g : words("--gravity", gravity, {"hanging", "none", "side", "side-", "upright"}))
      for (const std::string& i : words("--inertia", inertia, {"joint", "com"}))
        for (double a : numbers("--q0", q0))
          for (double b : numbers("--dq0", dq0))
            for (double h : numbers("--step", step))
              for (const std::string& e : plexus::split_comma_list(ekf_init))
                for (double l : numbers("--limit", limit)) setups.push_back({g, i, a, b, h, e, l});
    for (const std::string& a : plexus::split_comma_list(vdc_accel))
      if (a != "model" && (a.rfind("diff", 0) != 0 || numbers("--vdc-accel", a.substr(4)).front() <= 0))
        throw CLI::ValidationError("--vdc-accel", "unknown value " + a);
    const std::vector<double> thetas = numbers("--vdc-theta", theta);
    for (double th : thetas)
      if (th < 0.6 || th > 1.8)
        throw CLI::ValidationError("--vdc-theta", "must be in [0.6, 1.8] (the P-function's bounds)");
    readings = vdc_readings(plexus::split_comma_list(vdc_accel), thetas);
    const std::vector<Reading> ct = ct_readings(words("--ct-velocity", ct_vel, {"motor", "link"}),
                                                words("--ct-inertia", ct_inertia, {"links", "motors"}),
                                                words("--ct-accel", ct_accel, {"desired", "estimated"}));
    readings.insert(readings.end(), ct.begin(), ct.end());
    ts = numbers("--times", times);
    for (const SetUp& s : setups) {
      if (!(s.step > 0 && s.step <= 0.01)) throw CLI::ValidationError("--step", "must be in (0, 0.01]");
      if (s.ekf_init != "steady" && s.ekf_init != "zero" && s.ekf_init != "origin" &&
          (numbers("--ekf-init", s.ekf_init).front() < 0 || numbers("--ekf-init", s.ekf_init).front() > 2))
        throw CLI::ValidationError("--ekf-init", "steady, zero, origin or a fraction in [0, 2]: " + s.ekf_init);
    }
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  // Every (set-up, reading) run, in parallel.
  const std::size_t runs = setups.size() * readings.size();
  std::vector<std::vector<Figures>> result(runs);
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < runs;) {
      const SetUp& s = setups[i / readings.size()];
      const Trace t = simulate(s, readings[i % readings.size()], duration, seed);
      for (double T : ts) result[i].push_back(figures(t, s.step, T, hold));
      if ((i + 1) % 50 == 0) {
        std::lock_guard<std::mutex> lock(print);
        std::fprintf(stderr, "table4_fit: %zu of %zu runs\n", i + 1, runs);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (std::thread& th : pool) th.join();

  // Join: every set-up x VDC reading x CT+PD reading x T, scored by the worst relative error.
  struct Row {
    std::size_t setup, vdc, ct, t;
    double worst;
    double f[kFigures];
    bool extrapolated;
  };
  std::vector<Row> rows;
  for (std::size_t s = 0; s < setups.size(); ++s)
    for (std::size_t a = 0; a < readings.size(); ++a)
      for (std::size_t b = 0; b < readings.size(); ++b) {
        if (readings[a].controller != "vdc" || readings[b].controller != "ctpd") continue;
        for (std::size_t k = 0; k < ts.size(); ++k) {
          const Figures& v = result[s * readings.size() + a][k];
          const Figures& c = result[s * readings.size() + b][k];
          Row r{s, a, b, k, 0.0, {}, v.extrapolated || c.extrapolated};
          for (int i = 0; i < 7; ++i) r.f[i] = v.f[i], r.f[7 + i] = c.f[i];
          for (int i = 0; i < kFigures; ++i) r.worst = std::max(r.worst, std::abs(r.f[i] - kPaper[i]) / kPaper[i]);
          if (std::isnan(r.worst)) r.worst = std::numeric_limits<double>::infinity();
          rows.push_back(r);
        }
      }
  std::sort(rows.begin(), rows.end(), [](const Row& x, const Row& y) { return x.worst < y.worst; });

  auto describe = [&](const Row& r) {
    const SetUp& s = setups[r.setup];
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%s,%g,%g,%g,%s,%g,%s,%s,%g%s", s.gravity.c_str(), s.inertia.c_str(), s.q0, s.dq0,
                  s.step, s.ekf_init.c_str(), s.limit1, readings[r.vdc].name.c_str(), readings[r.ct].name.c_str(),
                  ts[r.t], r.extrapolated ? "*" : "");
    return std::string(buf);
  };
  const std::string header = "gravity,inertia,q0,dq0,step,ekf_init,limit1,vdc,ctpd,T,worst";
  if (!csv.empty()) {
    std::ofstream out(csv);
    if (!out) {
      std::fprintf(stderr, "table4_fit: cannot write --csv %s\n", csv.c_str());
      return 2;
    }
    out << header;
    for (const char* n : kFigureNames) out << ',' << n;
    out << '\n';
    for (const Row& r : rows) {
      out << describe(r) << ',' << r.worst;
      for (double f : r.f) out << ',' << f;
      out << '\n';
    }
  }
  std::printf("%zu runs, %zu rows; paper:", runs, rows.size());
  for (double p : kPaper) std::printf(" %g", p);
  std::printf("\n%s, then the 14 figures (* T past the simulated duration)\n", header.c_str());
  for (std::size_t i = 0; i < rows.size() && i < static_cast<std::size_t>(top); ++i) {
    std::printf("%s  worst %.3f |", describe(rows[i]).c_str(), rows[i].worst);
    for (double f : rows[i].f) std::printf(" %.3g", f);
    std::printf("\n");
  }
  return 0;
}
