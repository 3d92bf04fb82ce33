// icr_library_recorder (estimator; icr_estimator): learns the terrain ICR library that the
// ICR EKF's prior reset reads (docs/algorithms/skid_steer.md "Prior reset";
// common/algorithms/include/plexus/algorithms/skid_steer/terrain_icr_library.hpp). Ports
// bind to `<robot>/<port>` unless remapped.
//
//   in icr {y_l, y_r, x_G, sd_y_l, sd_y_r, sd_x_G} (IcrEstimate, of an ICR EKF that
//     re-converges after terrain changes, e.g. the AKF), truth/state {terrain}
//     (SkidSteerTruth: the label, as terrain_recorder does); out recorder {samples}
//     (in process only: it writes a file under `plexus sim`)
//   output (required; relative to the scenario file's folder), settle_s (15: seconds after
//   a terrain change before the estimate counts as converged on it), class_names ([])
//
// Every step at least settle_s into a terrain adds the estimate to that terrain's running
// mean and variance; the file is rewritten (atomically) each time 100 more samples exist.
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "plexus/algorithms/skid_steer/terrain_icr_library.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class IcrLibraryRecorderComponent final : public Component {
 public:
  explicit IcrLibraryRecorderComponent(const ComponentConfig& c)
      : Component(c),
        path_(scenario_relative_path(c, "output")),
        settle_s_(c.params().optional<double>("settle_s", 15.0)),
        icr_(add_input("icr", {"y_l", "y_r", "x_G", "sd_y_l", "sd_y_r", "sd_x_G"}, "IcrEstimate")),
        truth_(add_input("truth/state", {"terrain"}, "SkidSteerTruth")),
        out_(add_output("recorder", {"samples"}, "")) {
    if (!(settle_s_ >= 0.0)) c.params().fail("settle_s", "must be >= 0");
    if (c.params().has("class_names")) {
      int i = 0;
      for (const auto& n : c.params().sequence("class_names")) names_[i++] = n.Scalar();
    }
    comment_ = "recorded by service '" + c.name + "'";
  }

  void step(int64_t /*k*/, double t) override {
    if (!truth_.valid() || !icr_.valid()) return;
    const int terrain = static_cast<int>(std::lround(truth_[0]));
    if (terrain != terrain_) {
      terrain_ = terrain;
      since_ = t;
    }
    if (terrain < 0 || t - since_ < settle_s_) return;
    acc_.add(terrain, {icr_[0], icr_[1], icr_[2]}, {icr_[3], icr_[4], icr_[5]});
    out_[0] = static_cast<double>(++samples_);
    if (samples_ % 100 == 0) {
      try {
        alg::save_terrain_icr_library(path_, acc_.library(names_), comment_);
      } catch (const alg::TrainingFileError& e) {
        throw InputError(e.what());
      }
    }
  }

 private:
  std::string path_;
  double settle_s_;
  std::map<int, std::string> names_;
  std::string comment_;
  alg::TerrainIcrAccumulator acc_;
  int terrain_ = -1;
  double since_ = 0.0;
  long samples_ = 0;
  InputPort& icr_;
  InputPort& truth_;
  OutputPort& out_;
};

const ComponentRegistration kIcrLibraryRecorder{
    "icr_library_recorder", ComponentKind::estimator,
    "learns each terrain's converged ICRs into a terrain ICR library file",
    [](const ComponentConfig& c) { return std::make_unique<IcrLibraryRecorderComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
