// Terrain ICR library files and their accumulation (terrain_icr_library.hpp).
#include "plexus/algorithms/skid_steer/terrain_icr_library.hpp"
#include "text_tokens.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace plexus::algorithms {
namespace {

constexpr const char* kMagicIcrLibrary = "plexus-terrain-icr-library";

using detail::tokens;

}  // namespace

TerrainIcrLibrary load_terrain_icr_library(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw TrainingFileError(path + ": cannot open the terrain ICR library");
  auto fail = [&](std::size_t line, const std::string& what) -> void {
    throw TrainingFileError(path + ":" + std::to_string(line) + ": " + what);
  };
  auto number = [&](std::size_t line, const std::string& t, const char* what) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v))
      fail(line, std::string(what) + ": expected a finite number, got '" + t + "'");
    return v;
  };
  TerrainIcrLibrary lib;
  bool magic = false;
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    const auto t = tokens(line.substr(0, line.find('#')));
    if (t.empty()) continue;
    if (!magic) {
      if (t.size() != 2 || t[0] != kMagicIcrLibrary || t[1] != "1")
        fail(n, std::string("expected '") + kMagicIcrLibrary + " 1'");
      magic = true;
      continue;
    }
    if (t[0] != "class") fail(n, "unknown record '" + t[0] + "' (expected class)");
    if (t.size() != 10) fail(n, "class: expected id, name, y_l, y_r, x_G, sd_y_l, sd_y_r, sd_x_G, samples");
    const double id = number(n, t[1], "class id");
    if (id < 0 || id != std::floor(id)) fail(n, "class id: must be an integer >= 0");
    TerrainIcrPrior p;
    p.mean = {number(n, t[3], "y_l"), number(n, t[4], "y_r"), number(n, t[5], "x_G")};
    if (!(p.mean.y_l > p.mean.y_r)) fail(n, "y_l must be greater than y_r (left track left of the right one)");
    for (int i = 0; i < 3; ++i) {
      p.sd(i) = number(n, t[6 + i], "sd");
      if (!(p.sd(i) > 0.0)) fail(n, "sd: must be > 0");
    }
    const double samples = number(n, t[9], "samples");
    if (samples < 1 || samples != std::floor(samples)) fail(n, "samples: must be an integer >= 1");
    p.samples = static_cast<long>(samples);
    const int cls = static_cast<int>(id);
    if (lib.classes.count(cls)) fail(n, "class " + t[1] + " is listed twice");
    lib.classes[cls] = p;
    lib.names[cls] = t[2];
  }
  if (!magic) throw TrainingFileError(path + ": empty file (expected '" + std::string(kMagicIcrLibrary) + " 1')");
  if (lib.classes.empty()) throw TrainingFileError(path + ": no class records");
  return lib;
}

void save_terrain_icr_library(const std::string& path, const TerrainIcrLibrary& library, const std::string& comment) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) throw TrainingFileError(path + ": cannot write the terrain ICR library");
    out << "# plexus terrain ICR library: per terrain class, the ICRs the ICR EKF converged to\n"
           "# (docs/algorithms/skid_steer.md, \"Prior reset\")\n";
    if (!comment.empty()) out << "# " << comment << "\n";
    out << kMagicIcrLibrary << " 1\n# class id name y_l y_r x_G sd_y_l sd_y_r sd_x_G samples\n";
    char buf[256];
    for (const auto& [id, p] : library.classes) {
      const auto name = library.names.count(id) ? library.names.at(id) : "class" + std::to_string(id);
      std::snprintf(buf, sizeof buf, "class %d %s %.6g %.6g %.6g %.4g %.4g %.4g %ld\n", id, name.c_str(), p.mean.y_l,
                    p.mean.y_r, p.mean.x_G, p.sd(0), p.sd(1), p.sd(2), p.samples);
      out << buf;
    }
    if (!out.flush()) throw TrainingFileError(path + ": cannot write the terrain ICR library");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw TrainingFileError(path + ": cannot write the terrain ICR library (" + ec.message() + ")");
}

void TerrainIcrAccumulator::add(int id, const IcrParams& icr, const Eigen::Vector3d& filter_sd) {
  Moments& m = moments_[id];
  const Eigen::Vector3d x(icr.y_l, icr.y_r, icr.x_G);
  ++m.n;
  const Eigen::Vector3d d = x - m.mean;
  m.mean += d / static_cast<double>(m.n);
  m.m2 += d.cwiseProduct(x - m.mean);
  m.filter_var += filter_sd.cwiseProduct(filter_sd);
}

long TerrainIcrAccumulator::samples(int id) const {
  const auto it = moments_.find(id);
  return it == moments_.end() ? 0 : it->second.n;
}

TerrainIcrLibrary TerrainIcrAccumulator::library(const std::map<int, std::string>& names) const {
  TerrainIcrLibrary lib;
  lib.names = names;
  for (const auto& [id, m] : moments_) {
    if (m.n < 1) continue;
    const double n = static_cast<double>(m.n);
    const Eigen::Vector3d var =
        (m.n > 1 ? Eigen::Vector3d(m.m2 / (n - 1.0)) : Eigen::Vector3d::Zero()) + m.filter_var / n;
    TerrainIcrPrior p;
    p.mean = {m.mean(0), m.mean(1), m.mean(2)};
    p.sd = var.cwiseSqrt().cwiseMax(1e-6);
    p.samples = m.n;
    lib.classes[id] = p;
  }
  return lib;
}

}  // namespace plexus::algorithms
