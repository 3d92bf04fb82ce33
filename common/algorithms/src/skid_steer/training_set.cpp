// Terrain training files: format, loading with validation, writing
// (docs/algorithms/skid_steer.md, "Training data").
#include "plexus/algorithms/skid_steer/training_set.hpp"
#include "text_tokens.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

namespace {

constexpr const char* kMagicTraining = "plexus-terrain-training";
constexpr int kVersion = 1;

using detail::tokens;

class Parser {
 public:
  Parser(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw TrainingFileError(path_ + ":" + std::to_string(line) + ": " + what);
  }

  double number(std::size_t line, const std::string& t, const std::string& what) const {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail(line, what + ": expected a number, got '" + t + "'");
    if (!std::isfinite(v)) fail(line, what + ": must be finite, got '" + t + "'");
    return v;
  }

  long integer(std::size_t line, const std::string& t, const std::string& what) const {
    long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail(line, what + ": expected an integer, got '" + t + "'");
    return v;
  }

  void arity(std::size_t line, const std::vector<std::string>& tk, std::size_t n) const {
    if (tk.size() != n + 1) {
      fail(line, "'" + tk[0] + "' takes " + std::to_string(n) + " value" + (n == 1 ? "" : "s") + ", got " +
                     std::to_string(tk.size() - 1));
    }
  }

 private:
  std::string path_;
};

}  // namespace

FeatureLayout FeatureLayout::of(const PsdFeatureExtractor& e) {
  const PsdFeatureParams& p = e.params();
  return {p.sample_rate_hz, p.window_samples, p.min_hz, p.max_hz, p.taper, p.log10, e.size()};
}

std::string FeatureLayout::difference(const FeatureLayout& o) const {
  auto num = [](double v) { return validation::format_value(v); };
  if (sample_rate_hz != o.sample_rate_hz)
    return "sample_rate_hz " + num(sample_rate_hz) + " vs " + num(o.sample_rate_hz);
  if (window_samples != o.window_samples)
    return "window_samples " + num(window_samples) + " vs " + num(o.window_samples);
  if (min_hz != o.min_hz || max_hz != o.max_hz) {
    return "band_hz " + num(min_hz) + " " + num(max_hz) + " vs " + num(o.min_hz) + " " + num(o.max_hz);
  }
  if (taper != o.taper) return std::string("taper ") + to_string(taper) + " vs " + to_string(o.taper);
  if (log10 != o.log10)
    return std::string("scale ") + (log10 ? "log10" : "linear") + " vs " + (o.log10 ? "log10" : "linear");
  if (features != o.features)
    return "features " + num(static_cast<double>(features)) + " vs " + num(static_cast<double>(o.features));
  return "";
}

TrainingSet load_training_set(const std::string& path) {
  const Parser p(path);
  std::ifstream in(path);
  if (!in) p.fail(0, "cannot open the training file");
  TrainingSet set;
  std::set<std::string> seen;
  const std::vector<std::string> required = {"sample_rate_hz", "window_samples", "band_hz",
                                             "taper",          "scale",          "features"};
  bool magic = false;
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto tk = tokens(line);
    if (tk.empty() || tk[0][0] == '#') continue;
    const std::string& key = tk[0];
    if (!magic) {
      if (key != kMagicTraining)
        p.fail(line_no, std::string("expected the header '") + kMagicTraining + " 1', got '" + line + "'");
      p.arity(line_no, tk, 1);
      if (p.integer(line_no, tk[1], "version") != kVersion) {
        p.fail(line_no, "unsupported version " + tk[1] + " (this build reads version 1)");
      }
      magic = true;
      continue;
    }
    if (key == "sample") {
      for (const auto& r : required) {
        if (!seen.count(r)) p.fail(line_no, "header key '" + r + "' missing before the first sample");
      }
      const std::size_t n = set.layout.features;
      if (tk.size() != n + 2) {
        p.fail(line_no, "expected a class id and " + std::to_string(n) + " features, got " +
                            std::to_string(tk.size() - 1) + " values");
      }
      const long label = p.integer(line_no, tk[1], "class id");
      if (label < 0 || label > 1000000) p.fail(line_no, "class id must be in 0..1000000, got " + tk[1]);
      set.labels.push_back(static_cast<int>(label));
      for (std::size_t i = 0; i < n; ++i) {
        const double v = p.number(line_no, tk[i + 2], "feature " + std::to_string(i + 1));
        if (!set.layout.log10 && v < 0.0)
          p.fail(line_no, "feature " + std::to_string(i + 1) + ": a PSD must be >= 0, got " + tk[i + 2]);
        set.features.push_back(v);
      }
      continue;
    }
    if (!set.labels.empty()) p.fail(line_no, "header key '" + key + "' after the first sample");
    if (key == "class") {
      if (tk.size() < 3) p.fail(line_no, "'class' takes an id and a name");
      const long id = p.integer(line_no, tk[1], "class id");
      if (id < 0 || id > 1000000) p.fail(line_no, "class id must be in 0..1000000, got " + tk[1]);
      if (set.class_names.count(static_cast<int>(id))) p.fail(line_no, "class " + tk[1] + " named twice");
      std::string name = tk[2];
      for (std::size_t i = 3; i < tk.size(); ++i) name += " " + tk[i];
      set.class_names[static_cast<int>(id)] = name;
      continue;
    }
    bool known = false;
    for (const auto& r : required) known = known || r == key;
    if (!known) p.fail(line_no, "unknown key '" + key + "'");
    if (!seen.insert(key).second) p.fail(line_no, "header key '" + key + "' given twice");
    FeatureLayout& L = set.layout;
    if (key == "sample_rate_hz") {
      p.arity(line_no, tk, 1);
      L.sample_rate_hz = p.number(line_no, tk[1], key);
      if (!(L.sample_rate_hz > 0)) p.fail(line_no, "sample_rate_hz must be > 0, got " + tk[1]);
    } else if (key == "window_samples") {
      p.arity(line_no, tk, 1);
      const long w = p.integer(line_no, tk[1], key);
      if (w < 4 || w > 1000000) p.fail(line_no, "window_samples must be in 4..1000000, got " + tk[1]);
      L.window_samples = static_cast<int>(w);
    } else if (key == "band_hz") {
      p.arity(line_no, tk, 2);
      L.min_hz = p.number(line_no, tk[1], "band_hz min");
      L.max_hz = p.number(line_no, tk[2], "band_hz max");
      if (!(L.min_hz >= 0 && L.max_hz > L.min_hz)) p.fail(line_no, "band_hz must satisfy 0 <= min < max");
    } else if (key == "taper") {
      p.arity(line_no, tk, 1);
      try {
        L.taper = spectrum_taper_from_string(tk[1]);
      } catch (const std::invalid_argument&) {
        p.fail(line_no, "taper must be rectangular or hann, got '" + tk[1] + "'");
      }
    } else if (key == "scale") {
      p.arity(line_no, tk, 1);
      if (tk[1] != "linear" && tk[1] != "log10") p.fail(line_no, "scale must be linear or log10, got '" + tk[1] + "'");
      L.log10 = tk[1] == "log10";
    } else {  // features
      p.arity(line_no, tk, 1);
      const long n = p.integer(line_no, tk[1], key);
      if (n < 1 || n > 100000) p.fail(line_no, "features must be in 1..100000, got " + tk[1]);
      L.features = static_cast<std::size_t>(n);
    }
  }
  if (!magic) p.fail(0, "empty training file (expected the header 'plexus-terrain-training 1')");
  if (set.labels.empty()) p.fail(0, "no samples");
  return set;
}

TrainingSetWriter::TrainingSetWriter(const std::string& path, const FeatureLayout& layout,
                                     const std::map<int, std::string>& class_names, const std::string& comment)
    : path_(path), layout_(layout), out_(path, std::ios::trunc) {
  if (!out_) throw TrainingFileError(path + ":0: cannot open the training file for writing");
  out_ << "# plexus terrain training set: labelled PSD feature vectors (docs/algorithms/skid_steer.md)\n";
  if (!comment.empty()) out_ << "# " << comment << "\n";
  out_ << kMagicTraining << ' ' << kVersion << '\n';
  out_.precision(17);
  out_ << "sample_rate_hz " << layout.sample_rate_hz << '\n'
       << "window_samples " << layout.window_samples << '\n'
       << "band_hz " << layout.min_hz << ' ' << layout.max_hz << '\n'
       << "taper " << to_string(layout.taper) << '\n'
       << "scale " << (layout.log10 ? "log10" : "linear") << '\n'
       << "features " << layout.features << '\n';
  for (const auto& [id, name] : class_names) out_ << "class " << id << ' ' << name << '\n';
  out_.flush();
  if (!out_) throw TrainingFileError(path + ":0: cannot write the training file");
}

void TrainingSetWriter::append(int label, std::span<const double> features) {
  if (label < 0)
    throw std::invalid_argument("training_set_writer: label must be >= 0 (got " + std::to_string(label) + ")");
  if (features.size() != layout_.features) throw std::invalid_argument("training_set_writer: wrong number of features");
  out_ << "sample " << label;
  for (double v : features) out_ << ' ' << v;
  out_ << '\n';
  out_.flush();
  if (!out_) throw TrainingFileError(path_ + ":0: cannot write the training file");
  ++written_;
}

}  // namespace plexus::algorithms
