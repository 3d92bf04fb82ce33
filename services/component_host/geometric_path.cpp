// geometric_path (reference; component_host): a path h(x, y) = 0 and its derivatives at
// the measured position, for paper 003's path following (section 2;
// docs/algorithms/unicycle.md). Ports bind to `<robot>/<port>` unless remapped; the output
// names its IDL type (docs/topics.md).
//
//   in position {x, y} (PositionMeasurement);
//   out path {x, y, h, hx, hy, hxx, hxy, hyy} (PathSample):
//     h and its derivatives at the measured position, and (x, y) a nearby point ON the
//     path (three Gauss-Newton steps p <- p - h grad h / |grad h|^2), for plots and errors
//   shape: circle (center_x, center_y, radius) | line (point_x, point_y, normal_x,
//   normal_y) | ellipse (center_x, center_y, a, b, phi) | polynomial (terms: list of
//   [i, j, c] for c x^i y^j)                                                    003 section 2
//   (centres and points default to 0, the line's normal to (0, 1), phi to 0)
#include <cmath>
#include <memory>
#include <string>

#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class GeometricPathComponent final : public Component {
 public:
  explicit GeometricPathComponent(const ComponentConfig& c)
      : Component(c),
        path_(shape(c.params())),
        in_(add_input("position", {"x", "y"}, "PositionMeasurement")),
        out_(add_output("path", {"x", "y", "h", "hx", "hy", "hxx", "hxy", "hyy"}, "PathSample")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const Eigen::Vector2d p = vec2(in_);
    const alg::PathEvaluation e = path_.evaluate(p);
    Eigen::Vector2d q = p;  // a point of the path near p: Gauss-Newton on h(q) = 0
    for (int i = 0; i < 3; ++i) {
      const alg::PathEvaluation eq = i == 0 ? e : path_.evaluate(q);
      const double g2 = eq.gradient.squaredNorm();
      if (!(g2 > 1e-12)) break;
      q -= eq.h / g2 * eq.gradient;
    }
    const double v[] = {q.x(),           q.y(),          e.h, e.gradient.x(), e.gradient.y(), e.hessian(0, 0),
                        e.hessian(0, 1), e.hessian(1, 1)};
    for (std::size_t i = 0; i < 8; ++i) out_[i] = v[i];
  }

 private:
  static alg::PathShape shape(const YamlMap& p) {
    const auto s = p.required<std::string>("shape");
    const auto point = [&](const char* x, const char* y, double dx = 0.0, double dy = 0.0) {
      return Eigen::Vector2d(p.optional<double>(x, dx), p.optional<double>(y, dy));
    };
    if (s == "circle") return alg::CirclePath{point("center_x", "center_y"), p.required<double>("radius")};
    if (s == "line") return alg::LinePath{point("point_x", "point_y"), point("normal_x", "normal_y", 0.0, 1.0)};
    if (s == "ellipse")
      return alg::EllipsePath{point("center_x", "center_y"), p.required<double>("a"), p.required<double>("b"),
                              p.optional<double>("phi", 0.0)};
    if (s == "polynomial") {
      alg::PolynomialPath poly;
      for (const auto& term : p.sequence("terms")) {
        if (!term.IsSequence() || term.size() != 3) p.fail("terms", "each term is [i, j, c] for c x^i y^j");
        // Through number(), checked whole and in range before the conversion: yaml-cpp's
        // as<int>() threw its own exception for a word, and took 1e10.
        const double di = number(p, term[0], "terms"), dj = number(p, term[1], "terms");
        if (di != std::floor(di) || dj != std::floor(dj) || di < 0 || dj < 0 ||
            di + dj > alg::PolynomialPath::kMaxDegree)
          p.fail("terms",
                 "powers must be whole numbers >= 0 with i + j <= " + std::to_string(alg::PolynomialPath::kMaxDegree));
        poly.c(static_cast<int>(di), static_cast<int>(dj)) += number(p, term[2], "terms");
      }
      return poly;
    }
    p.fail("shape", "expected circle, line, ellipse or polynomial, got '" + s + "'");
  }

  alg::GeometricPath path_;
  InputPort& in_;
  OutputPort& out_;
};

const ComponentRegistration kGeometricPath{
    "geometric_path", ComponentKind::reference, "path h(x, y) = 0 and its derivatives at the position (paper 003)",
    [](const ComponentConfig& c) { return std::make_unique<GeometricPathComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
