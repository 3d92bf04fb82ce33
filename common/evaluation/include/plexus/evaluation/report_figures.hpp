// `plexus report`: the figures it draws from a run folder.
//
//   signal_figures   one figure per signal, one panel per quantity (report_panels.hpp), the
//                    robot's true state dashed under its estimates and measurements; one x-y
//                    path per robot; one figure per metric series
//   paper_figures    for each robot whose signals one of the papers' figures needs, that
//                    figure as the paper draws it (docs/scenarios.md, "plexus report"):
//                      000  the path against the reference and the tracking error V_t (53)
//                      001  the ICR estimates against truth, terrain switches marked
//                      002  the tilt estimates against truth and their error
//                      004  each link's tracking error and each joint's input torque
//                    their computed series (errors) are written to plots/data/*.csv
#pragma once

#include <vector>

#include "plexus/evaluation/report_figure.hpp"
#include "plexus/evaluation/report_inputs.hpp"

namespace plexus::scenario {

std::vector<Figure> signal_figures(const ReportInputs& in);

/// Writes the series the figures plot that the run folder lacks (plots/data/*.csv); throws
/// InputError when it cannot.
std::vector<Figure> paper_figures(const ReportInputs& in);

}  // namespace plexus::scenario
