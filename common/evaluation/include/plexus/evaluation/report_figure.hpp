// `plexus report`: the figures as data (figures of panels of curves) and the gnuplot script
// that draws them. Every figure has a title; every panel a title and both axis labels, each
// with its unit in brackets ("t [s]", "angle [rad]", "[-]" for a dimensionless quantity,
// "[unit not declared]" when the run folder does not know it). report_figures_test checks it
// on the figures and on the script.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plexus::scenario {

struct Curve {
  enum class Style { line, dashed, points };
  std::string file;   ///< CSV, relative to the run folder
  std::string x, y;   ///< gnuplot `using` expressions: a column number ("3") or "($3*1000)"
  std::string title;  ///< legend entry
  Style style = Style::line;
  int colour = 0;  ///< gnuplot linetype (an estimate and its truth share one); 0: black
};

/// A line across a panel: vertical at a time (a terrain switch, the start of a metric's
/// window) or horizontal at a value (a bound), labelled.
struct Marker {
  enum class Axis { x, y };
  Axis axis = Axis::x;
  double at = 0.0;
  std::string label;
  std::optional<std::pair<double, double>> extent;  ///< horizontal: from/to in x (default: the whole panel)
};

struct Panel {
  std::string title;
  std::string xlabel;  ///< "quantity [unit]"
  std::string ylabel;
  std::vector<Curve> curves;
  std::vector<Marker> markers;
  std::optional<std::pair<double, double>> xrange;
  bool equal_axes = false;  ///< an x-y path: a metre as long on both axes
  bool log_y = false;
};

struct Figure {
  std::string file;  ///< "plots/<name>.png", relative to the run folder
  std::string title;
  std::string caption;  ///< a sentence under the figure in report.html
  std::string section;  ///< "paper", "signals" or "series" (report.html's sections)
  std::string robot;    ///< the robot it shows ("" for none)
  int columns = 1;      ///< panels fill rows of this many columns
  std::vector<Panel> panels;
};

/// The gnuplot script (pngcairo) writing every figure; paths relative to the run folder.
std::string gnuplot_script(const std::vector<Figure>& figures);

}  // namespace plexus::scenario
