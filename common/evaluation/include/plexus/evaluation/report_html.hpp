// `plexus report`: report.html, the page to look at after a run. Static HTML and CSS only
// (no script, no network resource; readable in any browser, with or without JavaScript):
// the run's facts, the comparison table against the papers, the papers' figures, then every
// other figure by robot, each inline as <img src="plots/<name>.png"> with its caption.
#pragma once

#include <string>
#include <vector>

#include "plexus/evaluation/report_comparison.hpp"
#include "plexus/evaluation/report_figure.hpp"
#include "plexus/evaluation/report_inputs.hpp"

namespace plexus::scenario {

std::string report_html(const ReportInputs& in, const Comparison& comparison, const std::vector<Figure>& figures);

}  // namespace plexus::scenario
