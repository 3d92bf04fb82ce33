#include "plexus/algorithms/unicycle/geometric_path.hpp"

#include <cmath>
#include <string>
#include <type_traits>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

constexpr const char* kWhereGeometricPath = "geometric_path";

void validate(const CirclePath& c) {
  validation::require_finite(kWhereGeometricPath, "circle.center.x", c.center.x());
  validation::require_finite(kWhereGeometricPath, "circle.center.y", c.center.y());
  validation::require_positive(kWhereGeometricPath, "circle.radius", c.radius);
}

void validate(const LinePath& l) {
  validation::require_finite(kWhereGeometricPath, "line.point.x", l.point.x());
  validation::require_finite(kWhereGeometricPath, "line.point.y", l.point.y());
  validation::require_finite(kWhereGeometricPath, "line.normal.x", l.normal.x());
  validation::require_finite(kWhereGeometricPath, "line.normal.y", l.normal.y());
  validation::require_positive(kWhereGeometricPath, "|line.normal|", l.normal.norm());
}

void validate(const EllipsePath& e) {
  validation::require_finite(kWhereGeometricPath, "ellipse.center.x", e.center.x());
  validation::require_finite(kWhereGeometricPath, "ellipse.center.y", e.center.y());
  validation::require_positive(kWhereGeometricPath, "ellipse.a", e.a);
  validation::require_positive(kWhereGeometricPath, "ellipse.b", e.b);
  validation::require_finite(kWhereGeometricPath, "ellipse.phi", e.phi);
}

void validate(const PolynomialPath& p) {
  bool non_constant = false;
  for (int i = 0; i <= PolynomialPath::kMaxDegree; ++i) {
    for (int j = 0; j <= PolynomialPath::kMaxDegree; ++j) {
      const std::string name = "polynomial.c(" + std::to_string(i) + ", " + std::to_string(j) + ")";
      const double c = p.c(i, j);
      validation::require_finite(kWhereGeometricPath, name, c);
      if (i + j > PolynomialPath::kMaxDegree && c != 0.0) {
        validation::fail(kWhereGeometricPath, name,
                         "0 (total degree above " + std::to_string(PolynomialPath::kMaxDegree) + ")", c);
      }
      if (i + j > 0 && c != 0.0) non_constant = true;
    }
  }
  if (!non_constant)
    validation::fail(kWhereGeometricPath, "polynomial", "non-constant (some c(i, j) != 0 with i + j > 0)", 0.0);
}

PathEvaluation eval(const CirclePath& c, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - c.center;
  PathEvaluation e;
  e.h = d.squaredNorm() - c.radius * c.radius;
  e.gradient = 2.0 * d;
  e.hessian = 2.0 * Eigen::Matrix2d::Identity();
  return e;
}

PathEvaluation eval(const LinePath& l, const Eigen::Vector2d& p) {
  PathEvaluation e;
  e.h = l.normal.dot(p - l.point);
  e.gradient = l.normal;
  return e;  // Hessian zero
}

PathEvaluation eval(const EllipsePath& el, const Eigen::Vector2d& p) {
  // (u, w) = R(-phi) (p - c); h = (u/a)^2 + (w/b)^2 - 1 = d^T R D R^T d - 1, D = diag(1/a^2, 1/b^2).
  const double c = std::cos(el.phi), s = std::sin(el.phi);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  const Eigen::Matrix2d D = Eigen::Vector2d(1.0 / (el.a * el.a), 1.0 / (el.b * el.b)).asDiagonal();
  const Eigen::Matrix2d Q = R * D * R.transpose();
  const Eigen::Vector2d d = p - el.center;
  PathEvaluation e;
  e.h = d.dot(Q * d) - 1.0;
  e.gradient = 2.0 * Q * d;
  e.hessian = 2.0 * Q;
  return e;
}

PathEvaluation eval(const PolynomialPath& poly, const Eigen::Vector2d& p) {
  constexpr int N = PolynomialPath::kMaxDegree;
  // Powers x^k, y^k, k = 0..N (fixed-size, no allocation).
  double xp[N + 1], yp[N + 1];
  xp[0] = yp[0] = 1.0;
  for (int k = 1; k <= N; ++k) {
    xp[k] = xp[k - 1] * p.x();
    yp[k] = yp[k - 1] * p.y();
  }
  PathEvaluation e;
  double hx = 0, hy = 0, hxx = 0, hxy = 0, hyy = 0, h = 0;
  for (int i = 0; i <= N; ++i) {
    for (int j = 0; i + j <= N; ++j) {
      const double c = poly.c(i, j);
      if (c == 0.0) continue;
      h += c * xp[i] * yp[j];
      if (i >= 1) hx += c * i * xp[i - 1] * yp[j];
      if (j >= 1) hy += c * j * xp[i] * yp[j - 1];
      if (i >= 2) hxx += c * i * (i - 1) * xp[i - 2] * yp[j];
      if (j >= 2) hyy += c * j * (j - 1) * xp[i] * yp[j - 2];
      if (i >= 1 && j >= 1) hxy += c * i * j * xp[i - 1] * yp[j - 1];
    }
  }
  e.h = h;
  e.gradient = {hx, hy};
  e.hessian << hxx, hxy, hxy, hyy;
  return e;
}

}  // namespace

GeometricPath::GeometricPath(const PathShape& shape) : shape_(shape) {
  std::visit([](const auto& s) { validate(s); }, shape_);
}

PathEvaluation GeometricPath::evaluate(const Eigen::Vector2d& p) const {
  return std::visit([&p](const auto& s) { return eval(s, p); }, shape_);
}

}  // namespace plexus::algorithms
