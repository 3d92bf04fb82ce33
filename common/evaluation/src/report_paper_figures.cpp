// `plexus report`: the papers' own figures, for any run folder that has the signals they
// need (a single-family scenario or the main job). What each paper plots (docs/papers.md):
//   000 (Yan & Ma 2016) Figs. 2-7: the robot's path against the reference, and the position
//       tracking error V_t = sqrt((x - x_r)^2 + (y - y_r)^2) (eq. (53)) against time;
//   001 (Wu et al. 2015) Figs. 6 and 8: the ICR estimates y_l, y_r, x_G against their true
//       values across the terrain switches;
//   002 (Zhao et al. 2006) Fig. 4: the tilt estimates against the true tilt, and the tilt
//       estimate error, in degrees;
//   004 (Liu et al. 2018) Figs. 3-6: the tracking error of each link (Table 4 reads it in
//       mrad) and the input torque of each joint.
// A figure of 002 or 004 spans the window of the scenario's metrics on that robot (the
// papers' 5 s), when they have one; 000 and 001 span the run.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/report_figures.hpp"
#include "plexus/scenario/expectation.hpp"
#include "plexus/scenario/format.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace fs = std::filesystem;
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;

using Column = std::vector<double>;

/// Index of the latest sample at or before each time asked, times asked in increasing order
/// (a metric's "reference held at each sample of the signal").
class Held {
 public:
  explicit Held(const Column& times) : t_(times) {}
  /// Row of the latest sample at or before `time`, or -1 before the first.
  long at(double time) {
    while (next_ < t_.size() && t_[next_] <= time + 1e-9) ++next_;
    return static_cast<long>(next_) - 1;
  }

 private:
  const Column& t_;
  std::size_t next_ = 0;
};

/// Writes plots/data/<name>.csv (header, then the rows of `columns`); returns its path
/// relative to the run folder.
std::string write_data(const ReportInputs& in, const std::string& name, const std::vector<std::string>& header,
                       const std::vector<Column>& columns) {
  const std::string rel = "plots/data/" + name + ".csv";
  fs::create_directories(in.dir / "plots" / "data");
  std::ofstream out(in.dir / rel);
  std::string line;
  for (const auto& h : header) line += (line.empty() ? "" : ",") + h;
  out << line << '\n';
  const std::size_t rows = columns.empty() ? 0 : columns[0].size();
  for (std::size_t r = 0; r < rows; ++r) {
    line.clear();
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) line += ',';
      append_number(line, columns[c][r]);
    }
    out << line << '\n';
  }
  if (!out) throw InputError((in.dir / rel).string() + ": cannot write file");
  return rel;
}

std::vector<std::pair<std::string, YAML::Node>> services_of(const ReportInputs& in, const std::string& robot) {
  std::vector<std::pair<std::string, YAML::Node>> out;
  if (in.scenario["services"] && in.scenario["services"].IsMap())
    for (const auto& s : in.scenario["services"])
      if (s.second["robot"] && s.second["robot"].Scalar() == robot) out.emplace_back(s.first.Scalar(), s.second);
  return out;
}

/// Whether a service of `robot` is of a type that takes part in `figure` (ComponentType::figures).
bool has_service_in(const ReportInputs& in, const std::string& robot, const std::string& figure) {
  for (const auto& [name, node] : services_of(in, robot))
    if (node["type"] && scenario::takes_part_in(node["type"].Scalar(), figure)) return true;
  return false;
}

/// Whether `robot`'s plant is of a type that takes part in `figure`.
bool plant_in(const ReportInputs& in, const std::string& robot, const std::string& figure) {
  return scenario::takes_part_in(in.plant_type(robot), figure);
}

std::vector<YAML::Node> metric_entries(const ReportInputs& in) {
  std::vector<YAML::Node> out;
  if (in.scenario["metrics"] && in.scenario["metrics"].IsSequence())
    for (const auto& m : in.scenario["metrics"]) out.push_back(m);
  return out;
}

/// A metric entry's name (its type when unnamed).
std::string metric_name(const YAML::Node& entry) {
  const std::string n = scalar_or_empty(entry, "name");
  return n.empty() ? scalar_or_empty(entry, "type") : n;
}

/// The window [from, to] of the metrics that read any of `signals` and give one.
std::optional<std::pair<double, double>> metric_window(const ReportInputs& in, const std::set<std::string>& signals) {
  std::optional<std::pair<double, double>> w;
  for (const auto& m : metric_entries(in)) {
    bool reads = false;
    for (const char* key : {"signal", "reference", "estimate", "truth", "state"})
      reads = reads || signals.count(scalar_or_empty(m, key)) > 0;
    if (!reads || (!m["from"] && !m["to"])) continue;
    const double from = m["from"] ? m["from"].as<double>() : 0.0;
    const double to = m["to"] ? m["to"].as<double>() : in.duration();
    w = w ? std::make_pair(std::min(w->first, from), std::max(w->second, to)) : std::make_pair(from, to);
  }
  return w;
}

std::optional<Expectation> expectation_of(const ReportInputs& in, const std::string& metric) {
  const YAML::Node ex = in.scenario["expectations"];
  if (!ex || !ex.IsMap() || !ex[metric] || !ex[metric].IsScalar()) return std::nullopt;
  Expectation e;
  if (!parse_expectation(metric, ex[metric].Scalar(), e)) return std::nullopt;
  return e;
}

std::vector<int> columns_of(const ReportTable& t, const std::vector<std::string>& fields) {
  std::vector<int> out;
  for (const auto& f : fields) out.push_back(t.column(f));
  return out;
}

std::string t_column_label() { return "t [s]"; }

// --- paper 000 ------------------------------------------------------------------------

std::optional<Figure> paper000(const ReportInputs& in, const std::string& robot) {
  const ReportTable* truth = in.truth(robot);
  const ReportTable* ref = in.signal(robot + "/reference");
  if (!plant_in(in, robot, "paper000.plant") || !has_service_in(in, robot, "paper000.controller") || !truth || !ref)
    return {};
  if (!truth->column("x") || !truth->column("y") || !ref->column("x") || !ref->column("y")) return {};

  // Which of the paper's simulations: state feedback (Figs. 2-3), output feedback on exact
  // positions (Figs. 4-5) or on the RFID grid (Figs. 6-7).
  std::string figs = "Figs. 4-5";
  for (const auto& [name, node] : services_of(in, robot))
    if (scenario::takes_part_in(scalar_or_empty(node, "type"), "paper000.controller") &&
        scalar_or_empty(node, "feedback") == "state")
      figs = "Figs. 2-3";
  if (figs != "Figs. 2-3" && in.scenario["robots"][robot]["sensors"])
    for (const auto& s : in.scenario["robots"][robot]["sensors"])
      if (scalar_or_empty(s.second, "kind") == "rfid_grid") figs = "Figs. 6-7";

  // V_t (eq. (53)) at each sample of the true state, the reference held.
  const auto tr = read_columns(in, *truth, columns_of(*truth, {"t", "x", "y"}));
  const auto rr = read_columns(in, *ref, columns_of(*ref, {"t", "x", "y"}));
  Column t, vt;
  Held held(rr[0]);
  for (std::size_t i = 0; i < tr[0].size(); ++i) {
    const long k = held.at(tr[0][i]);
    if (k < 0) continue;
    t.push_back(tr[0][i]);
    vt.push_back(
        std::hypot(tr[1][i] - rr[1][static_cast<std::size_t>(k)], tr[2][i] - rr[2][static_cast<std::size_t>(k)]));
  }
  const std::string data = write_data(in, robot + ".tracking_error", {"t", "V_t"}, {t, vt});

  Figure f;
  f.file = "plots/paper000." + robot + ".png";
  f.title = "Paper 000 (Yan & Ma 2016), " + figs + ": robot " + robot + " tracking the reference";
  f.caption =
      "Left: the robot's path (its true state) against the reference, as the paper's trajectory figure. "
      "Right: the position tracking error V_t = sqrt((x - x_r)^2 + (y - y_r)^2) (eq. (53)), "
      "log scale, with the bounds of the scenario's expectations on it over their windows.";
  f.section = "paper";
  f.robot = robot;
  f.columns = 2;
  Panel path;
  path.title = "path in the plane";
  path.xlabel = "x [m]";
  path.ylabel = "y [m]";
  path.equal_axes = true;
  path.curves.push_back({ref->path, std::to_string(ref->column("x")), std::to_string(ref->column("y")),
                         "reference (x_r, y_r)", Curve::Style::dashed, 0});
  path.curves.push_back({truth->path, std::to_string(truth->column("x")), std::to_string(truth->column("y")),
                         "robot (x, y)", Curve::Style::line, 1});
  f.panels.push_back(std::move(path));

  Panel err;
  err.title = "position tracking error V_t (eq. (53))";
  err.xlabel = t_column_label();
  err.ylabel = "V_t [m]";
  err.log_y = true;
  err.curves.push_back({data, "1", "2", "V_t", Curve::Style::line, 1});
  for (const auto& m : metric_entries(in)) {
    const std::string type = scalar_or_empty(m, "type");
    if ((type != "error_max" && type != "error_mean") || scalar_or_empty(m, "signal") != truth->name ||
        scalar_or_empty(m, "reference") != ref->name)
      continue;
    const auto e = expectation_of(in, metric_name(m));
    if (!e) continue;
    const double from = m["from"] ? m["from"].as<double>() : 0.0;
    const double to = m["to"] ? m["to"].as<double>() : in.duration();
    err.markers.push_back({Marker::Axis::y, e->bound,
                           std::string(type == "error_max" ? "max" : "mean") + " V_t " + e->op_text() + " " +
                               format_number(e->bound) + " m (" + metric_name(m) + ")",
                           std::make_pair(from, to)});
    const bool marked = std::any_of(err.markers.begin(), err.markers.end(),
                                    [&](const Marker& k) { return k.axis == Marker::Axis::x && k.at == from; });
    if (from > 0 && !marked)
      err.markers.push_back({Marker::Axis::x, from, "t = " + format_number(from) + " s", std::nullopt});
  }
  f.panels.push_back(std::move(err));
  return f;
}

// --- paper 001 ------------------------------------------------------------------------

/// "skid/icr (skid_ekf: AKF, prior reset)", "r1/icr_plain (ekf_plain: EKF)": the paper
/// calls the ICR EKF with the terrain-triggered reset the AKF.
std::string icr_label(const ReportInputs& in, const ReportTable& e) {
  const YAML::Node s = in.scenario["services"] ? in.scenario["services"][e.producer] : YAML::Node();
  if (!s || !scenario::takes_part_in(scalar_or_empty(s, "type"), "paper001.estimator")) return e.name;
  const bool adaptive = scalar_or_empty(s, "adaptive_reset") == "true";
  const std::string reset_mode = scalar_or_empty(s, "reset_mode");
  const std::string mode = reset_mode.empty() ? "covariance" : reset_mode;
  return e.name + " (" + e.producer + ": " + (adaptive ? "AKF, " + mode + " reset" : std::string("EKF")) + ")";
}

std::optional<Figure> paper001(const ReportInputs& in, const std::string& robot) {
  const ReportTable* truth = in.truth(robot);
  if (!plant_in(in, robot, "paper001.plant") || !truth) return {};
  const std::vector<std::string> icrs = {"y_l", "y_r", "x_G"};
  for (const auto& c : icrs)
    if (!truth->column(c)) return {};
  std::vector<const ReportTable*> estimates;
  for (const auto& t : in.signals)
    if (t.robot == robot && &t != truth && t.column("y_l") && t.column("y_r") && t.column("x_G"))
      estimates.push_back(&t);
  if (estimates.empty()) return {};

  // The terrain switches: where the true terrain changes, named after the plant's schedule.
  std::vector<Marker> switches;
  if (truth->column("terrain")) {
    const auto tt = read_columns(in, *truth, {1, truth->column("terrain")});
    const YAML::Node schedule = in.scenario["robots"][robot]["plant"]["schedule"];
    for (std::size_t i = 1; i < tt[0].size(); ++i) {
      if (tt[1][i] == tt[1][i - 1]) continue;
      std::string name = "terrain " + format_number(tt[1][i]);
      if (schedule && schedule.IsSequence())
        for (const auto& entry : schedule)
          if (entry.IsSequence() && entry.size() == 2 && entry[0].as<double>() <= tt[0][i] + 1e-9)
            name = entry[1].Scalar();
      switches.push_back({Marker::Axis::x, tt[0][i], "to " + name, std::nullopt});
    }
  }

  Figure f;
  f.file = "plots/paper001." + robot + ".png";
  f.title = "Paper 001 (Wu et al. 2015), Figs. 6 and 8: ICR estimates of " + robot + " across terrain switches";
  f.caption =
      "The ICR coordinates y_l, y_r (tracks) and x_G (body) estimated by each estimator of the robot against "
      "their true values (dashed); dotted lines: the terrain switches.";
  f.section = "paper";
  f.robot = robot;
  const std::map<std::string, std::string> names = {
      {"y_l", "left track ICR y_l"}, {"y_r", "right track ICR y_r"}, {"x_G", "body ICR x_G"}};
  for (const auto& c : icrs) {
    Panel p;
    p.title = names.at(c);
    p.xlabel = t_column_label();
    p.ylabel = c + " [m]";
    int colour = 1;
    for (const ReportTable* e : estimates)
      p.curves.push_back({e->path, "1", std::to_string(e->column(c)), icr_label(in, *e), Curve::Style::line, colour++});
    p.curves.push_back({truth->path, "1", std::to_string(truth->column(c)), "truth", Curve::Style::dashed, 0});
    p.markers = switches;
    f.panels.push_back(std::move(p));
  }
  return f;
}

// --- paper 002 ------------------------------------------------------------------------

std::optional<Figure> paper002(const ReportInputs& in, const std::string& robot) {
  const ReportTable* truth = in.truth(robot);
  if (!plant_in(in, robot, "paper002.plant") || !truth || !truth->column("theta")) return {};
  std::vector<const ReportTable*> estimates;
  for (const auto& t : in.signals)
    if (t.robot == robot && &t != truth && !in.is_sensor(t) && t.column("theta")) estimates.push_back(&t);
  if (estimates.empty()) return {};

  std::set<std::string> names = {truth->name};
  for (const auto* e : estimates) names.insert(e->name);
  const auto window = metric_window(in, names);

  const auto tr = read_columns(in, *truth, {1, truth->column("theta")});
  Figure f;
  f.file = "plots/paper002." + robot + ".png";
  f.title = "Paper 002 (Zhao et al. 2006), Fig. 4: tilt estimates of " + robot + " and their error";
  f.caption =
      "Top: each tilt estimate against the true tilt (dashed). Bottom: the tilt estimate error (estimate - "
      "truth, the truth at the estimate's step) with the filter's own 1-sigma band (dashed) where it gives one "
      "and at most two filters are compared" +
      std::string(window ? "; over the window of the scenario's metrics." : ".");
  f.section = "paper";
  f.robot = robot;
  Panel tilt;
  tilt.title = "tilt: estimates against truth";
  tilt.xlabel = t_column_label();
  tilt.ylabel = "tilt [deg]";
  tilt.xrange = window;
  Panel err;
  err.title = "tilt estimate error";
  err.xlabel = t_column_label();
  err.ylabel = "tilt error [deg]";
  err.xrange = window;
  int colour = 1;
  for (const ReportTable* e : estimates) {
    const bool has_std = e->column("theta_std") > 0;
    const auto er =
        read_columns(in, *e, has_std ? columns_of(*e, {"t", "theta", "theta_std"}) : columns_of(*e, {"t", "theta"}));
    Column t, est, error, sd;
    Held held(tr[0]);
    for (std::size_t i = 0; i < er[0].size(); ++i) {
      const long k = held.at(er[0][i]);
      if (k < 0) continue;
      t.push_back(er[0][i]);
      est.push_back(er[1][i] * kDegPerRad);
      error.push_back((er[1][i] - tr[1][static_cast<std::size_t>(k)]) * kDegPerRad);
      sd.push_back(has_std ? er[2][i] * kDegPerRad : 0.0);
    }
    std::string stem = e->name.substr(robot.size() + 1);
    std::replace(stem.begin(), stem.end(), '/', '.');
    const std::string data = write_data(in, robot + ".tilt_error." + stem,
                                        {"t", "estimate_deg", "error_deg", "std_deg"}, {t, est, error, sd});
    // "bal/attitude (ukf_augmented)": the filter an attitude_filter runs, else the type.
    const YAML::Node service = in.scenario["services"] ? in.scenario["services"][e->producer] : YAML::Node();
    const std::string filter =
        service && service["filter"] ? service["filter"].Scalar() : in.component_type(e->producer);
    const std::string label = e->name + (filter.empty() ? "" : " (" + filter + ")");
    tilt.curves.push_back({data, "1", "2", label, Curve::Style::line, colour});
    err.curves.push_back({data, "1", "3", label, Curve::Style::line, colour});
    if (has_std && estimates.size() <= 2) {  // more bands than that hide the errors
      err.curves.push_back({data, "1", "4", "+-1 sigma (" + e->name + " theta_std)", Curve::Style::dashed, colour});
      err.curves.push_back({data, "1", "(-$4)", "", Curve::Style::dashed, colour});
    }
    ++colour;
  }
  tilt.curves.push_back(
      {truth->path, "1", "($" + std::to_string(truth->column("theta")) + "*180/pi)", "truth", Curve::Style::dashed, 0});
  f.panels.push_back(std::move(tilt));
  f.panels.push_back(std::move(err));
  return f;
}

// --- paper 004 ------------------------------------------------------------------------

std::optional<Figure> paper004(const ReportInputs& in, const std::string& robot) {
  const ReportTable* truth = in.truth(robot);
  const ReportTable* ref = in.signal(robot + "/reference");
  const ReportTable* cmd = in.signal(robot + "/cmd");
  if (!plant_in(in, robot, "paper004.plant") || !truth || !ref || !cmd) return {};
  int n = 0;
  while (truth->column("q" + std::to_string(n + 1)) && ref->column("q" + std::to_string(n + 1)) &&
         cmd->column("u" + std::to_string(n + 1)))
    ++n;
  if (n == 0) return {};
  const auto window = metric_window(in, {truth->name, ref->name, cmd->name});

  std::vector<int> tc{1}, rc{1};
  for (int j = 1; j <= n; ++j) {
    tc.push_back(truth->column("q" + std::to_string(j)));
    rc.push_back(ref->column("q" + std::to_string(j)));
  }
  const auto tr = read_columns(in, *truth, tc);
  const auto rr = read_columns(in, *ref, rc);
  std::vector<Column> cols(static_cast<std::size_t>(n) + 1);
  Held held(rr[0]);
  for (std::size_t i = 0; i < tr[0].size(); ++i) {
    const long k = held.at(tr[0][i]);
    if (k < 0) continue;
    if (window && (tr[0][i] < window->first - 1e-9 || tr[0][i] > window->second + 1e-9)) continue;
    cols[0].push_back(tr[0][i]);
    for (std::size_t j = 1; j <= static_cast<std::size_t>(n); ++j)
      cols[j].push_back((tr[j][i] - rr[j][static_cast<std::size_t>(k)]) * 1000.0);
  }
  std::vector<std::string> header{"t"};
  for (int j = 1; j <= n; ++j) header.push_back("e" + std::to_string(j) + "_mrad");
  const std::string data = write_data(in, robot + ".joint_errors", header, cols);

  // Table 4's settling band, from the scenario's settling_time metrics on this arm.
  std::map<std::string, double> band;  // field -> rad
  for (const auto& m : metric_entries(in))
    if (scalar_or_empty(m, "type") == "settling_time" && scalar_or_empty(m, "signal") == truth->name && m["band"])
      band[scalar_or_empty(m, "field")] = m["band"].as<double>();

  Figure f;
  f.file = "plots/paper004." + robot + ".png";
  const std::string controller = [&] {
    for (const auto& [name, node] : services_of(in, robot))
      if (const std::string type = scalar_or_empty(node, "type"); scenario::takes_part_in(type, "paper004.controller"))
        return name + ": " + type;
    return cmd->producer;
  }();
  f.title = "Paper 004 (Liu et al. 2018), Figs. 3-6: link tracking errors and joint torques of " + robot + " (" +
            controller + ")";
  f.caption =
      "Top: the tracking error of each link, q_i - q_ri (Figs. 3-4; Table 4 reads it in mrad), with the "
      "settling band of the scenario's settling-time metrics. Bottom: the input torque of each joint "
      "(Figs. 5-6)" +
      std::string(window ? "; over the window of the scenario's metrics." : ".");
  f.section = "paper";
  f.robot = robot;
  f.columns = n;
  for (int j = 1; j <= n; ++j) {
    const std::string q = "q" + std::to_string(j);
    Panel p;
    p.title = "link " + std::to_string(j) + " tracking error e" + std::to_string(j) + " = " + q + " - q_r" +
              std::to_string(j);
    p.xlabel = t_column_label();
    p.ylabel = "e" + std::to_string(j) + " [mrad]";
    p.xrange = window;
    p.curves.push_back(
        {data, "1", std::to_string(j + 1), "e" + std::to_string(j) + " (" + controller + ")", Curve::Style::line, j});
    if (auto b = band.find(q); b != band.end()) {
      p.markers.push_back({Marker::Axis::y, b->second * 1000.0,
                           "settling band +-" + format_number(b->second * 1000.0) + " mrad", std::nullopt});
      p.markers.push_back({Marker::Axis::y, -b->second * 1000.0, "", std::nullopt});
    }
    f.panels.push_back(std::move(p));
  }
  for (int j = 1; j <= n; ++j) {
    const std::string u = "u" + std::to_string(j);
    Panel p;
    p.title = "joint " + std::to_string(j) + " input torque " + u;
    p.xlabel = t_column_label();
    p.ylabel = u + " [N m]";
    p.xrange = window;
    p.curves.push_back(
        {cmd->path, "1", std::to_string(cmd->column(u)), u + " (" + controller + ")", Curve::Style::line, j});
    f.panels.push_back(std::move(p));
  }
  return f;
}

}  // namespace

std::vector<Figure> paper_figures(const ReportInputs& in) {
  std::vector<Figure> out;
  for (const auto& robot : in.robots())
    for (auto* make : {paper000, paper001, paper002, paper004})
      if (auto f = make(in, robot)) out.push_back(std::move(*f));
  return out;
}

}  // namespace plexus::scenario
