// The gnuplot script of `plexus report`'s figures: one PNG per figure, its panels in a
// multiplot grid, each with its title, axis labels, legend and markers.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/report_figure.hpp"

namespace plexus::scenario {
namespace {

/// A gnuplot single-quoted string ('' is a literal quote).
std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string num(double v) { return format_number(v); }

void write_markers(std::ostream& gp, const Panel& p) {
  int tag = 1;
  for (const auto& m : p.markers) {
    if (!std::isfinite(m.at)) continue;
    if (m.axis == Marker::Axis::x) {
      gp << "set arrow " << tag << " from first " << num(m.at) << ", graph 0 to first " << num(m.at)
         << ", graph 1 nohead dt 3 lw 1.5 lc rgb '#505050' back\n";
      if (!m.label.empty())  // along the line, from its foot: clear of the legend at the top
        gp << "set label " << tag << " " << quote(m.label) << " at first " << num(m.at)
           << ", graph 0.03 left rotate by 90 offset -0.6,0 font ',9' tc rgb '#303030' front\n";
    } else {
      const std::string from = m.extent ? "first " + num(m.extent->first) : std::string("graph 0");
      const std::string to = m.extent ? "first " + num(m.extent->second) : std::string("graph 1");
      gp << "set arrow " << tag << " from " << from << ", first " << num(m.at) << " to " << to << ", first "
         << num(m.at) << " nohead dt 4 lw 1.5 lc rgb '#c00000' back\n";
      if (!m.label.empty())  // above the line, ending where it ends: inside the panel
        gp << "set label " << tag << " " << quote(m.label) << " at " << to << ", first " << num(m.at)
           << " right offset -0.4,0.6 font ',9' tc rgb '#c00000' front\n";
    }
    ++tag;
  }
}

void write_panel(std::ostream& gp, const Panel& p, bool key_outside) {
  gp << "set title " << quote(p.title) << "\nset xlabel " << quote(p.xlabel) << "\nset ylabel " << quote(p.ylabel)
     << "\n";
  if (p.xrange) gp << "set xrange [" << num(p.xrange->first) << ":" << num(p.xrange->second) << "]\n";
  if (p.equal_axes) gp << "set size ratio -1\n";
  if (p.log_y) gp << "set logscale y\nset format y '%g'\n";
  // A lone curve is named by the panel's title: no legend.
  if (p.curves.size() <= 1)
    gp << "unset key\n";
  else
    gp << (key_outside ? "set key outside right top Left reverse\n" : "set key inside top right opaque\n");
  write_markers(gp, p);
  std::string sep = "plot ";
  for (const auto& c : p.curves) {
    gp << sep << quote(c.file) << " every ::1 using " << c.x << ":" << c.y;
    switch (c.style) {
      case Curve::Style::points: gp << " with points pt 7 ps 0.25"; break;
      case Curve::Style::dashed: gp << " with lines dt 2 lw 1.5"; break;
      case Curve::Style::line: gp << " with lines lw 1.5"; break;
    }
    gp << (c.colour > 0 ? " lt " + std::to_string(c.colour) : std::string(" lc rgb 'black'")) << " title "
       << quote(c.title);
    sep = ", \\\n  ";
  }
  if (p.curves.empty()) gp << "plot NaN notitle";
  gp << "\nunset arrow\nunset label\nunset logscale\nset format y '% h'\nset autoscale\nset size noratio\n";
}

}  // namespace

std::string gnuplot_script(const std::vector<Figure>& figures) {
  std::ostringstream gp;
  gp << "# Written by plexus report: every figure of the report. Run from the run folder:\n"
     << "#   gnuplot plots/report.gp\n"
     << "set datafile separator ','\nset grid\n"
     // A palette whose every colour reads on white (gnuplot's fifth is a pale yellow).
     << "set linetype 1 lc rgb '#1f77b4'\nset linetype 2 lc rgb '#d62728'\nset linetype 3 lc rgb '#2ca02c'\n"
     << "set linetype 4 lc rgb '#ff7f0e'\nset linetype 5 lc rgb '#9467bd'\nset linetype 6 lc rgb '#8c564b'\n"
     << "set linetype 7 lc rgb '#e377c2'\nset linetype 8 lc rgb '#17becf'\nset linetype 9 lc rgb '#7f7f7f'\n"
     << "set linetype 10 lc rgb '#bcbd22'\nset linetype cycle 10\n";
  for (const auto& f : figures) {
    const int columns = std::max(1, f.columns);
    const int rows = static_cast<int>((f.panels.size() + static_cast<std::size_t>(columns) - 1) / columns);
    const int width = columns == 1 ? 1100 : 620 * columns;
    // A panel at equal scales (a path in the plane) gets a row about as tall as it is wide:
    // in a 280-pixel row it took a third of the width, and its x tick labels ran together.
    const bool equal = std::any_of(f.panels.begin(), f.panels.end(), [](const Panel& p) { return p.equal_axes; });
    const int row_height = columns == 1 ? (equal ? 760 : 280) : 460;
    const int height = 70 + std::max(1, rows) * row_height;
    gp << "\n# " << f.title << "\n"
       << "set terminal pngcairo size " << width << "," << height << " noenhanced font 'sans,10'\n"
       << "set output " << quote(f.file) << "\n"
       << "set multiplot layout " << std::max(1, rows) << "," << columns << " title " << quote(f.title)
       << " font ',13'\n";
    // One column: the same margins on every panel, so that their time axes line up, and
    // room on the right for the longest legend entry.
    if (columns == 1) {
      std::size_t longest = 0;
      for (const auto& p : f.panels)
        if (p.curves.size() > 1)
          for (const auto& c : p.curves) longest = std::max(longest, c.title.size());
      gp << "set lmargin 12\nset rmargin " << std::clamp<std::size_t>(longest + 8, 16, 60) << "\n";
    }
    for (const auto& p : f.panels) write_panel(gp, p, columns == 1);
    gp << "unset multiplot\nunset lmargin\nunset rmargin\nset output\n";
  }
  return gp.str();
}

}  // namespace plexus::scenario
