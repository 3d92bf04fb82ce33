// `plexus report`'s figures of every signal, trajectory and metric series.
#include <string>

#include "plexus/evaluation/report_figures.hpp"
#include "plexus/evaluation/report_panels.hpp"

namespace plexus::scenario {
namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

/// "from wmr_observer (heading_observer)" / "sensor position (position_sensor)" /
/// "true state of the unicycle plant".
std::string producer_text(const ReportInputs& in, const ReportTable& t) {
  if (const std::string type = in.component_type(t.producer); !type.empty())
    return "from " + t.producer + " (" + type + ")";
  if (in.is_sensor(t)) {
    const std::string key = t.name.substr(t.robot.size() + 1);
    const YAML::Node s = in.scenario["robots"][t.robot]["sensors"][key];
    return "sensor " + key + (s["type"] ? " (" + s["type"].Scalar() + ")" : std::string());
  }
  if (!t.robot.empty() && t.name == t.robot + "/truth/state")
    return "true state of the " + in.plant_type(t.robot) + " plant";
  return t.producer.empty() ? "" : "from " + t.producer;
}

Figure signal_figure(const ReportInputs& in, const ReportTable& t) {
  Figure f;
  f.file = "plots/" + t.stem + ".png";
  const std::string producer = producer_text(in, t);
  f.title = t.name + (producer.empty() ? "" : ", " + producer);
  f.section = "signals";
  f.robot = t.robot;
  const ReportTable* truth = in.truth(t.robot);
  if (truth == &t) truth = nullptr;
  f.caption = "Each field of " + t.name + " against time, one panel per quantity" +
              (truth ? "; dashed: the same field of the robot's true state." : ".");
  std::vector<FieldUnit> fields;
  for (const auto& name : t.fields()) fields.push_back({name, t.unit(name)});
  int colour = 1;
  for (const auto& g : group_fields(fields)) {
    Panel p;
    p.title = g.fields.size() == 1 && g.fields[0] == g.quantity ? g.quantity : g.quantity + ": " + join(g.fields);
    p.xlabel = "t [s]";
    p.ylabel = axis_label(g.quantity, g.unit);
    for (const auto& field : g.fields) {
      p.curves.push_back({t.path, "1", std::to_string(t.column(field)), field, Curve::Style::line, colour});
      if (truth && truth->column(field) && truth->unit(field) == g.unit)
        p.curves.push_back(
            {truth->path, "1", std::to_string(truth->column(field)), field + " (truth)", Curve::Style::dashed, colour});
      ++colour;
    }
    f.panels.push_back(std::move(p));
  }
  return f;
}

bool planar(const ReportTable& t) {
  const auto ux = t.unit("x"), uy = t.unit("y");
  return t.column("x") && t.column("y") && (!ux || *ux == "m") && (!uy || *uy == "m");
}

Figure trajectory_figure(const ReportInputs& in, const std::string& robot) {
  Figure f;
  f.file = "plots/" + robot + ".trajectory.png";
  f.title = robot + ": paths in the plane";
  f.caption = "y against x of the robot's true state and of every other signal of " + robot +
              " with x and y (reference, estimates; measurements as points).";
  f.section = "signals";
  f.robot = robot;
  Panel p;
  p.title = "path (equal scales)";
  const ReportTable* truth = in.truth(robot);
  p.xlabel = axis_label("x", truth->unit("x"));
  p.ylabel = axis_label("y", truth->unit("y"));
  p.equal_axes = true;
  int colour = 1;
  for (const auto& t : in.signals) {
    if (t.robot != robot || !planar(t)) continue;
    p.curves.push_back({t.path, std::to_string(t.column("x")), std::to_string(t.column("y")), t.name,
                        in.is_sensor(t) ? Curve::Style::points : Curve::Style::line, colour++});
  }
  f.panels.push_back(std::move(p));
  return f;
}

/// The unit of a metric's series: from the suffix of its name (report_panels.hpp), else from
/// its type: a ratio is dimensionless, a value_* statistic has the unit of its field.
std::optional<std::string> series_unit(const ReportInputs& in, const std::string& metric) {
  if (auto unit = metric_unit(metric)) return unit;
  const YAML::Node metrics = in.scenario["metrics"];
  if (!metrics || !metrics.IsSequence()) return std::nullopt;
  for (const auto& m : metrics) {
    const std::string type = m["type"] ? m["type"].Scalar() : "";
    if ((m["name"] ? m["name"].Scalar() : type) != metric) continue;
    if (type == "ratio" || (type.size() > 6 && type.compare(type.size() - 6, 6, "_ratio") == 0)) return std::string();
    if (type.rfind("value_", 0) == 0 && m["signal"] && m["field"] && !m["scale"])
      if (const ReportTable* t = in.signal(m["signal"].Scalar())) return t->unit(m["field"].Scalar());
  }
  return std::nullopt;
}

Figure series_figure(const ReportInputs& in, const ReportTable& t) {
  Figure f;
  f.file = "plots/series." + t.stem + ".png";
  f.title = "metric " + t.name + ": the series it summarises";
  f.caption = "The time series behind the metric " + t.name + " (metrics.json holds its summary).";
  f.section = "series";
  const std::optional<std::string> unit = series_unit(in, t.name);
  Panel p;
  p.title = t.name;
  p.xlabel = "t [s]";
  p.ylabel = axis_label(t.name, unit);  // the metric's own name says more than "length"
  p.curves.push_back({t.path, "1", "2", t.name, Curve::Style::line, 1});
  f.panels.push_back(std::move(p));
  return f;
}

}  // namespace

std::vector<Figure> signal_figures(const ReportInputs& in) {
  std::vector<Figure> out;
  for (const auto& robot : in.robots()) {
    if (const ReportTable* truth = in.truth(robot); truth && planar(*truth))
      out.push_back(trajectory_figure(in, robot));
    for (const auto& t : in.signals)
      if (t.robot == robot) out.push_back(signal_figure(in, t));
  }
  for (const auto& t : in.signals)
    if (t.robot.empty()) out.push_back(signal_figure(in, t));
  for (const auto& t : in.series) out.push_back(series_figure(in, t));
  return out;
}

}  // namespace plexus::scenario
