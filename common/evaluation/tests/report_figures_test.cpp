// plexus report's figures: which fields share a panel (one quantity and unit per panel),
// the papers' figures a run folder gets, and that every figure has a title and every panel
// axis labels with units, in the figures and in the gnuplot script. No gnuplot is run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/report_comparison.hpp"
#include "plexus/evaluation/report_figures.hpp"
#include "plexus/evaluation/report_html.hpp"
#include "plexus/evaluation/report_panels.hpp"
#include "plexus/evaluation/run_folder.hpp"
#include "plexus/scenario/executor.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario {
namespace {

namespace fs = std::filesystem;
using Fields = std::vector<std::string>;

std::map<std::string, Fields> by_quantity(const std::vector<FieldGroup>& groups) {
  std::map<std::string, Fields> out;
  for (const auto& g : groups) {
    EXPECT_EQ(out.count(g.quantity + unit_text(g.unit)), 0u) << "two panels for " << g.quantity;
    out[g.quantity + " " + unit_text(g.unit)] = g.fields;
  }
  return out;
}

TEST(ReportPanels, SkidSteerIcrEstimateIsFivePanelsNotOne) {
  // The ICR EKF's output (IcrEstimate): 10 fields from 0.01 m to 37 m, unreadable on one axis.
  const auto g = by_quantity(group_fields({{"x", "m"},
                                           {"y", "m"},
                                           {"theta", "rad"},
                                           {"y_l", "m"},
                                           {"y_r", "m"},
                                           {"x_G", "m"},
                                           {"resets", ""},
                                           {"sd_y_l", "m"},
                                           {"sd_y_r", "m"},
                                           {"sd_x_G", "m"}}));
  const std::map<std::string, Fields> expected = {
      {"position [m]", {"x", "y"}},
      {"angle [rad]", {"theta"}},
      {"length [m]", {"y_l", "y_r", "x_G"}},  // the ICR coordinates, together
      {"resets [-]", {"resets"}},
      {"standard deviation [m]", {"sd_y_l", "sd_y_r", "sd_x_G"}},
  };
  EXPECT_EQ(g, expected);
}

TEST(ReportPanels, GroupsByUnitAcrossNames) {
  // A flexible-joint arm's true state: link and motor angles share the angle panel.
  const auto g = by_quantity(group_fields({{"q1", "rad"},
                                           {"q2", "rad"},
                                           {"dq1", "rad/s"},
                                           {"dq2", "rad/s"},
                                           {"phi1", "rad"},
                                           {"phi2", "rad"},
                                           {"tau1", "N m"},
                                           {"tau2", "N m"}}));
  const std::map<std::string, Fields> expected = {
      {"angle [rad]", {"q1", "q2", "phi1", "phi2"}},
      {"angular rate [rad/s]", {"dq1", "dq2"}},
      {"torque [N m]", {"tau1", "tau2"}},
  };
  EXPECT_EQ(g, expected);
  // The attitude estimate: the spread apart from the tilt, the drift with the tilt rate.
  const auto a =
      by_quantity(group_fields({{"theta", "rad"}, {"theta_dot", "rad/s"}, {"drift", "rad/s"}, {"theta_std", "rad"}}));
  EXPECT_EQ(a.at("angle [rad]"), Fields{"theta"});
  EXPECT_EQ(a.at("angular rate [rad/s]"), (Fields{"theta_dot", "drift"}));
  EXPECT_EQ(a.at("standard deviation [rad]"), Fields{"theta_std"});
  // A position in another unit than a length is not a position.
  EXPECT_EQ(by_quantity(group_fields({{"x", "rad"}})).count("angle [rad]"), 1u);
}

TEST(ReportPanels, DimensionlessAndUndeclaredFieldsShareOnlyTheirStem) {
  const auto g = by_quantity(group_fields({{"class", ""},
                                           {"confidence", ""},
                                           {"z3", ""},
                                           {"z4", ""},
                                           {"windows", ""},
                                           {"q1", std::nullopt},
                                           {"q2", std::nullopt},
                                           {"x", std::nullopt}}));
  const std::map<std::string, Fields> expected = {
      {"class [-]", {"class"}},     {"confidence [-]", {"confidence"}},      {"z [-]", {"z3", "z4"}},
      {"windows [-]", {"windows"}}, {"q [unit not declared]", {"q1", "q2"}}, {"x [unit not declared]", {"x"}},
  };
  EXPECT_EQ(g, expected);
  EXPECT_EQ(axis_label("angle", "rad"), "angle [rad]");
  EXPECT_EQ(axis_label("class", ""), "class [-]");
}

TEST(ReportPanels, MetricUnitFromTheNameSuffix) {
  EXPECT_EQ(metric_unit("wmr_steady_max_error_m"), "m");
  EXPECT_EQ(metric_unit("arm_rms_e1_mrad"), "mrad");
  EXPECT_EQ(metric_unit("bal_ukf_error_std_deg"), "deg");
  EXPECT_EQ(metric_unit("arm_settling_time_1_s"), "s");
  EXPECT_EQ(metric_unit("arm_max_torque_1_nm"), "N m");
  EXPECT_EQ(metric_unit("skid_classifier_accuracy"), "");
  EXPECT_EQ(metric_unit("observer_decay_rate"), std::nullopt);
}

// --- a run folder of the main job, 6 s ------------------------------------------------

/// The units of the messages of four_robots.yaml, as wire_types.cpp declares them (this
/// test does not link the DDS layer).
std::optional<std::string> test_units(const std::string& message, const std::string& field) {
  static const std::map<std::string, std::string> units = {
      {"x", "m"},         {"y", "m"},          {"theta", "rad"},          {"y_l", "m"},       {"y_r", "m"},
      {"x_G", "m"},       {"sd_y_l", "m"},     {"sd_y_r", "m"},           {"sd_x_G", "m"},    {"resets", ""},
      {"model_age", "s"}, {"terrain", ""},     {"a_z", "m/s^2"},          {"v_l", "m/s"},     {"v_r", "m/s"},
      {"v", "m/s"},       {"omega", "rad/s"},  {"theta_dot", "rad/s"},    {"drift", "rad/s"}, {"theta_std", "rad"},
      {"torque", "N m"},  {"x_ddot", "m/s^2"}, {"theta_ddot", "rad/s^2"}, {"gyro", "rad/s"},  {"acc_x", "m/s^2"},
      {"acc_z", "m/s^2"}, {"class", ""},       {"confidence", ""},        {"windows", ""},    {"votes", ""},
      {"dx", "m/s"},      {"dy", "m/s"},       {"ddx", "m/s^2"},          {"ddy", "m/s^2"},   {"z3", ""},
      {"z4", ""},         {"L", "1/s"}};
  if (message.empty()) return std::nullopt;
  if (auto it = units.find(field); it != units.end()) return it->second;
  static const std::vector<std::pair<std::string, std::string>> joints = {
      {"dddq", "rad/s^3"}, {"ddq", "rad/s^2"}, {"dq", "rad/s"}, {"q", "rad"}, {"dphi", "rad/s"},
      {"phi", "rad"},      {"dtau", "N m/s"},  {"tau", "N m"},  {"u", "N m"}};
  for (const auto& [prefix, unit] : joints)
    if (field.rfind(prefix, 0) == 0 && field.size() > prefix.size() &&
        std::isdigit(static_cast<unsigned char>(field[prefix.size()])))
      return unit;
  return std::nullopt;
}

class MainJobFolder : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("plexus_report_figures_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    const std::string file = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/four_robots.yaml";
    Scenario sc = load_scenario(
        file, {parse_override("duration=6"), parse_override("metrics.0.from=5"), parse_override("metrics.1.from=5")});
    const RunLog log = run_scenario(sc);
    write_run_folder(dir_, sc, log, evaluate(sc, log), 1.0, test_units);
    in_ = new ReportInputs(read_report_inputs(dir_));
  }
  static void TearDownTestSuite() {
    delete in_;
    in_ = nullptr;
    fs::remove_all(dir_);
  }
  static const Figure& figure(const std::vector<Figure>& figures, const std::string& file) {
    auto it = std::find_if(figures.begin(), figures.end(), [&](const Figure& f) { return f.file == file; });
    if (it == figures.end()) throw std::runtime_error("no figure " + file);
    return *it;
  }
  static std::vector<std::string> curve_titles(const Panel& p) {
    std::vector<std::string> out;
    for (const auto& c : p.curves) out.push_back(c.title);
    return out;
  }
  static inline fs::path dir_;
  static inline ReportInputs* in_ = nullptr;
};

TEST_F(MainJobFolder, SignalIndexCarriesUnits) {
  const ReportTable* icr = in_->signal("skid/icr");
  ASSERT_NE(icr, nullptr);
  EXPECT_EQ(icr->unit("y_l"), "m");
  EXPECT_EQ(icr->unit("resets"), "");
  EXPECT_EQ(icr->producer, "skid_ekf");
  EXPECT_EQ(icr->robot, "skid");
  EXPECT_TRUE(fs::is_regular_file(dir_ / "signals.json"));
}

TEST_F(MainJobFolder, IcrEstimatePanelsHoldOneQuantityEach) {
  const auto figures = signal_figures(*in_);
  const Figure& f = figure(figures, "plots/skid.icr.png");
  std::map<std::string, std::vector<std::string>> panels;
  for (const auto& p : f.panels) panels[p.ylabel] = curve_titles(p);
  const std::map<std::string, std::vector<std::string>> expected = {
      {"position [m]", {"x", "x (truth)", "y", "y (truth)"}},
      {"angle [rad]", {"theta", "theta (truth)"}},
      {"length [m]", {"y_l", "y_l (truth)", "y_r", "y_r (truth)", "x_G", "x_G (truth)"}},
      {"resets [-]", {"resets"}},
      {"standard deviation [m]", {"sd_y_l", "sd_y_r", "sd_x_G"}},
      {"time [s]", {"model_age"}},
  };
  EXPECT_EQ(panels, expected);
}

TEST_F(MainJobFolder, EachPaperHasItsFigure) {
  const auto figures = paper_figures(*in_);
  ASSERT_EQ(figures.size(), 4u);
  const Figure& wmr = figure(figures, "plots/paper000.wmr.png");
  ASSERT_EQ(wmr.panels.size(), 2u);
  EXPECT_TRUE(wmr.panels[0].equal_axes);  // the path, x against y
  EXPECT_EQ(curve_titles(wmr.panels[0]), (std::vector<std::string>{"reference (x_r, y_r)", "robot (x, y)"}));
  EXPECT_EQ(wmr.panels[1].ylabel, "V_t [m]");
  EXPECT_TRUE(fs::is_regular_file(dir_ / "plots/data/wmr.tracking_error.csv"));
  ASSERT_GE(wmr.panels[1].markers.size(), 2u);  // the steady-state bounds of the expectations
  EXPECT_EQ(wmr.panels[1].markers[0].at, 0.05);

  const Figure& skid = figure(figures, "plots/paper001.skid.png");
  ASSERT_EQ(skid.panels.size(), 3u);
  for (const auto& p : skid.panels) {
    EXPECT_EQ(curve_titles(p), (std::vector<std::string>{"skid/icr (skid_ekf: AKF, prior reset)", "truth"}));
    EXPECT_EQ(p.curves.back().style, Curve::Style::dashed);
  }
  EXPECT_EQ(skid.panels[2].ylabel, "x_G [m]");

  const Figure& bal = figure(figures, "plots/paper002.bal.png");
  ASSERT_EQ(bal.panels.size(), 2u);
  EXPECT_EQ(bal.panels[1].ylabel, "tilt error [deg]");
  ASSERT_TRUE(bal.panels[1].xrange);  // the metrics' window (0..5 s)
  EXPECT_EQ(bal.panels[1].xrange->first, 0.0);

  const Figure& arm = figure(figures, "plots/paper004.arm.png");
  EXPECT_EQ(arm.columns, 2);
  ASSERT_EQ(arm.panels.size(), 4u);
  EXPECT_EQ(arm.panels[0].ylabel, "e1 [mrad]");
  EXPECT_EQ(arm.panels[3].ylabel, "u2 [N m]");
  EXPECT_EQ(arm.panels[0].markers.size(), 2u);  // the +-1.15 mrad settling band
}

TEST_F(MainJobFolder, NoPaperFigureWithoutItsSignals) {
  // The same folder without the skid-steer truth: no figure of paper 001, the others stay.
  ReportInputs in = *in_;
  in.signals.erase(std::remove_if(in.signals.begin(), in.signals.end(),
                                  [](const ReportTable& t) { return t.name == "skid/truth/state"; }),
                   in.signals.end());
  const auto figures = paper_figures(in);
  EXPECT_EQ(figures.size(), 3u);
  for (const auto& f : figures) EXPECT_EQ(f.file.find("paper001"), std::string::npos);
}

TEST_F(MainJobFolder, EveryFigureHasTitleAxisLabelsAndUnits) {
  auto figures = paper_figures(*in_);
  for (auto& f : signal_figures(*in_)) figures.push_back(std::move(f));
  ASSERT_GT(figures.size(), 30u);
  const std::regex with_unit(".+ \\[[^\\]]+\\]$");
  for (const auto& f : figures) {
    EXPECT_FALSE(f.title.empty()) << f.file;
    ASSERT_FALSE(f.panels.empty()) << f.file;
    for (const auto& p : f.panels) {
      EXPECT_FALSE(p.title.empty()) << f.file;
      EXPECT_TRUE(std::regex_match(p.xlabel, with_unit)) << f.file << ": x label '" << p.xlabel << "'";
      EXPECT_TRUE(std::regex_match(p.ylabel, with_unit)) << f.file << ": y label '" << p.ylabel << "'";
      EXPECT_EQ(p.ylabel.find("unit not declared"), std::string::npos) << f.file << ": " << p.ylabel;
      EXPECT_FALSE(p.curves.empty()) << f.file << ": " << p.title;
    }
  }
  // The script: each figure's output is followed by its multiplot title, and each panel's
  // title by its x and y labels, each with a unit.
  const std::string gp = gnuplot_script(figures);
  std::istringstream lines(gp);
  std::vector<std::string> l;
  for (std::string s; std::getline(lines, s);) l.push_back(s);
  const std::regex output("^set output '.+\\.png'$"), multiplot("^set multiplot layout [0-9]+,[0-9]+ title '.+' .*$");
  const std::regex title("^set title '.+'$"), xlabel("^set xlabel '.+ \\[[^\\]]+\\]'$"),
      ylabel("^set ylabel '.+ \\[[^\\]]+\\]'$");
  std::size_t outputs = 0, panels = 0;
  for (std::size_t i = 0; i < l.size(); ++i) {
    if (std::regex_match(l[i], output)) {
      ++outputs;
      ASSERT_LT(i + 1, l.size());
      EXPECT_TRUE(std::regex_match(l[i + 1], multiplot)) << l[i] << " then " << l[i + 1];
    }
    if (l[i].rfind("set title ", 0) == 0) {
      ++panels;
      ASSERT_LT(i + 2, l.size());
      EXPECT_TRUE(std::regex_match(l[i], title)) << l[i];
      EXPECT_TRUE(std::regex_match(l[i + 1], xlabel)) << l[i] << " then " << l[i + 1];
      EXPECT_TRUE(std::regex_match(l[i + 2], ylabel)) << l[i] << " then " << l[i + 2];
    }
  }
  std::size_t expected_panels = 0;
  for (const auto& f : figures) expected_panels += f.panels.size();
  EXPECT_EQ(outputs, figures.size());
  EXPECT_EQ(panels, expected_panels);
}

TEST_F(MainJobFolder, HtmlHasTheTableAndEveryFigure) {
  auto figures = paper_figures(*in_);
  for (auto& f : signal_figures(*in_)) figures.push_back(std::move(f));
  const Comparison c = compare(*in_);
  ASSERT_EQ(c.rows.size(), 13u);
  const std::string html = report_html(*in_, c, figures);
  std::size_t rows = 0, images = 0;
  for (std::size_t p = html.find("<tr class="); p != std::string::npos; p = html.find("<tr class=", p + 1)) ++rows;
  for (std::size_t p = html.find("<img src=\"plots/"); p != std::string::npos;
       p = html.find("<img src=\"plots/", p + 1))
    ++images;
  EXPECT_EQ(rows, c.rows.size());
  EXPECT_EQ(images, figures.size());
  EXPECT_NE(html.find("<th>paper</th><th>ours</th><th>bound</th><th>result</th>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("http"), std::string::npos);  // nothing from the network
}

TEST(ReportScript, APanelAtEqualScalesGetsARowAboutAsTallAsTheFigureIsWide) {
  // A path in the plane (set size ratio -1) in a row 280 pixels tall took a third of the
  // figure's width, and its x tick labels ran together (issue 31).
  Figure f;
  f.file = "plots/r1.trajectory.png";
  f.title = "r1: paths in the plane";
  Panel p;
  p.title = "path (equal scales)";
  p.xlabel = "x [m]";
  p.ylabel = "y [m]";
  p.equal_axes = true;
  p.curves.push_back({"signals/r1.csv", "2", "3", "r1/truth/state", Curve::Style::line, 1});
  f.panels.push_back(p);
  const std::string gp = gnuplot_script({f});
  std::smatch m;
  ASSERT_TRUE(std::regex_search(gp, m, std::regex("set terminal pngcairo size ([0-9]+),([0-9]+)"))) << gp;
  const int width = std::stoi(m[1]), height = std::stoi(m[2]);
  EXPECT_GE(height * 3, width * 2) << "canvas " << width << "x" << height;
  EXPECT_NE(gp.find("set size ratio -1"), std::string::npos);
}

}  // namespace
}  // namespace plexus::scenario
