// `plexus report`: what it reads from a run folder (run_folder.hpp): the resolved scenario,
// metrics.json, the CSV headers of signals/ and series/, and the units of signals.json.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

namespace plexus::scenario {

/// One CSV of the run folder (a signal, or a metric's series) and what is known of it.
struct ReportTable {
  std::string name;                               ///< the signal ("wmr/truth/state") or the metric
  std::string stem;                               ///< file name without .csv ("wmr.truth.state")
  std::string path;                               ///< relative to the run folder ("signals/wmr.truth.state.csv")
  std::string robot;                              ///< the robot it belongs to ("" for none)
  std::string producer;                           ///< the component that produced it ("" if unknown)
  std::vector<std::string> columns;               ///< the header: t, step, fields...
  std::vector<std::optional<std::string>> units;  ///< per column (t: "s")

  /// 1-based gnuplot column of a field, or 0.
  int column(const std::string& field) const;
  /// Unit of a field: "m", "" dimensionless, nullopt not declared (or no such field).
  std::optional<std::string> unit(const std::string& field) const;
  /// The data fields (the columns after t and, for signals, step).
  std::vector<std::string> fields() const;
};

struct ReportInputs {
  std::filesystem::path dir;
  YAML::Node scenario;               ///< scenario.resolved.yaml
  nlohmann::ordered_json metrics;    ///< metrics.json
  std::vector<ReportTable> signals;  ///< signals/*.csv, by name
  std::vector<ReportTable> series;   ///< series/*.csv, by name

  const ReportTable* signal(const std::string& name) const;
  /// The robot's true state signal (`<robot>/truth/state`), or nullptr.
  const ReportTable* truth(const std::string& robot) const;
  /// The robots of the scenario, in file order.
  std::vector<std::string> robots() const;
  /// A robot's plant type ("" if none).
  std::string plant_type(const std::string& robot) const;
  /// The type of a service or sensor component named `component` ("" if none).
  std::string component_type(const std::string& component) const;
  /// True when the signal is the output of a sensor of its robot (measured, plotted as points).
  bool is_sensor(const ReportTable& t) const;
  double duration() const;
};

/// Reads a run folder. Throws InputError (naming the folder or file) when it is not one.
/// A folder written before signals.json existed reads with every unit not declared.
ReportInputs read_report_inputs(const std::filesystem::path& dir);

/// The values of some columns of a CSV of the run folder, row by row: `out[i]` is column
/// `columns[i]` (1-based). Throws InputError naming the file and line of a bad number.
std::vector<std::vector<double>> read_columns(const ReportInputs& in, const ReportTable& t,
                                              const std::vector<int>& columns);

}  // namespace plexus::scenario
