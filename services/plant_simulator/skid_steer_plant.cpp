// skid_steer (plant; plant_simulator): the skid-steer robot of paper 001 (ICR kinematics,
// terrain schedule and vibration; docs/algorithms/skid_steer.md has every parameter with
// its default and the paper's value). Ports bind to <robot>/<port> unless remapped; the
// output names its IDL type (docs/topics.md).
//
//   in cmd {v_l, v_r} (TrackCommand); out truth/state {x, y, theta, y_l, y_r, x_G,
//     terrain, a_z, v_l, v_r} (SkidSteerTruth: true ICRs, terrain id, body z-acceleration,
//     applied track speeds)
//   terrains: {name: {y_l, y_r, x_G, floor_rms, resonances: [[f_hz, zeta, rms], ...]}}
//     (default: the paper's A concrete, B tile, C grass; ids in the order given)
//   schedule: [[start_s, terrain name], ...] (default: the first terrain throughout)
//   x0, y0, theta0 (0), vibration_reference_speed (0.5), vibration_speed_exponent (1), gravity (9.81)
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

std::vector<alg::TerrainSpec> terrains(const YamlMap& p, std::map<std::string, int>& ids) {
  std::vector<alg::TerrainSpec> out;
  if (!p.has("terrains")) {
    out = alg::paper_terrains();
  } else {
    const YamlMap t = p.map("terrains");
    for (const auto& name : t.keys()) {
      const YamlMap s = t.map(name);
      alg::TerrainSpec spec;
      spec.name = name;
      spec.icr = {s.required<double>("y_l"), s.required<double>("y_r"), s.required<double>("x_G")};
      spec.vibration.floor_rms = s.optional<double>("floor_rms", 0.0);
      if (s.has("resonances")) {
        for (const auto& r : s.sequence("resonances")) {
          const auto v = numbers(s, r, "resonances", 3);
          spec.vibration.resonances.push_back({v[0], v[1], v[2]});
        }
      }
      s.reject_unknown();
      out.push_back(spec);
    }
    if (out.empty()) p.fail("terrains", "needs at least one terrain");
  }
  for (std::size_t i = 0; i < out.size(); ++i) ids[out[i].name] = static_cast<int>(i);
  return out;
}

alg::SkidSteerPlantParams plant_params(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  alg::SkidSteerPlantParams s;
  std::map<std::string, int> ids;
  s.terrains = terrains(p, ids);
  if (p.has("schedule")) {
    s.schedule.clear();
    for (const auto& e : p.sequence("schedule")) {
      if (!e.IsSequence() || e.size() != 2 || !e[1].IsScalar()) {
        throw InputError(p.where(e) + ": " + p.key_path("schedule") + ": expected [start_s, terrain name]");
      }
      const auto it = ids.find(e[1].Scalar());
      if (it == ids.end()) {
        throw InputError(p.where(e) + ": " + p.key_path("schedule") + ": unknown terrain '" + e[1].Scalar() + "'");
      }
      s.schedule.push_back({number(p, e[0], "schedule"), it->second});
    }
  }
  s.initial_pose = {p.optional<double>("x0", 0.0), p.optional<double>("y0", 0.0), p.optional<double>("theta0", 0.0)};
  s.step = c.period();
  s.reference_speed = p.optional<double>("vibration_reference_speed", s.reference_speed);
  s.speed_exponent = p.optional<double>("vibration_speed_exponent", s.speed_exponent);
  s.gravity = p.optional<double>("gravity", s.gravity);
  return s;
}

class SkidSteerPlantComponent final : public Component {
 public:
  explicit SkidSteerPlantComponent(const ComponentConfig& c)
      : Component(c),
        plant_(plant_params(c)),
        rng_(c.seed),
        cmd_(add_input("cmd", {"v_l", "v_r"}, "TrackCommand")),
        out_(add_output("truth/state", {"x", "y", "theta", "y_l", "y_r", "x_G", "terrain", "a_z", "v_l", "v_r"},
                        "SkidSteerTruth")) {}

  void step(int64_t k, double t) override {
    if (k > 0) {
      u_ = cmd_.valid() ? alg::TrackSpeeds{cmd_[0], cmd_[1]} : alg::TrackSpeeds{};
      // The step from t - h to t, with the terrain at its start.
      plant_.step(t - plant_.params().step, u_, rng_);
    }
    const alg::SkidSteerState& s = plant_.state();
    const double v[] = {
        s.pose.x, s.pose.y, s.pose.theta, s.icr.y_l, s.icr.y_r, s.icr.x_G, static_cast<double>(s.terrain),
        s.a_z,    u_.v_l,   u_.v_r};
    for (std::size_t i = 0; i < std::size(v); ++i) out_[i] = v[i];
  }

 private:
  alg::SkidSteerPlant plant_;
  alg::Rng rng_;
  alg::TrackSpeeds u_{};
  InputPort& cmd_;
  OutputPort& out_;
};

const ComponentRegistration kSkidSteerPlant{
    "skid_steer",
    ComponentKind::plant,
    "skid-steer ICR kinematics with a terrain schedule and vibration (paper 001); "
    "in cmd {v_l, v_r}, out state {x, y, theta, y_l, y_r, x_G, terrain, a_z, v_l, v_r}",
    [](const ComponentConfig& c) { return std::make_unique<SkidSteerPlantComponent>(c); },
    {"paper001.plant"}};

}  // namespace
}  // namespace plexus::scenario
