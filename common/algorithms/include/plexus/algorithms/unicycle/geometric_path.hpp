// Geometric paths h(x, y) = 0 for path following (paper 003, section 2).
//
// The controller needs h, its gradient (h_x, h_y) and its Hessian (h_xx, h_xy, h_yy)
// at the robot position (paper 003, eqs. (3)-(4), (16)). Paths are a closed set held
// in a std::variant: no heap, no virtual call, a jump table in evaluate(); a new
// shape is a new struct plus one overload. Theorem 2 of paper 003 asks for
// h_x^2 + h_y^2 > 0 on the path and derivatives bounded by polynomials; every
// shape here satisfies both (the polynomial one only if the user's curve is
// non-degenerate, which cannot be checked in general).
#pragma once

#include <array>
#include <variant>

#include <Eigen/Core>

namespace plexus::algorithms {

/// h and its derivatives at one point.
struct PathEvaluation {
  double h = 0.0;
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();  ///< (h_x, h_y)
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();   ///< [[h_xx, h_xy], [h_xy, h_yy]]
};

/// h = (x - cx)^2 + (y - cy)^2 - r^2 (paper 003, section 5: cx = cy = 0, r = 1).
struct CirclePath {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< m
  double radius = 1.0;                               ///< m, > 0
};

/// h = n . (p - point): signed distance times |n| to the line through `point` with normal n.
struct LinePath {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();     ///< m, a point on the line
  Eigen::Vector2d normal = Eigen::Vector2d(0.0, 1.0);  ///< non-zero; h has units m * |normal|
};

/// h = (u / a)^2 + (w / b)^2 - 1 with (u, w) = R(-phi) (p - center): an ellipse with
/// semi-axes a (along the rotated x axis) and b, rotated by phi.
struct EllipsePath {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< m
  double a = 2.0;                                    ///< m, > 0
  double b = 1.0;                                    ///< m, > 0
  double phi = 0.0;                                  ///< rad
};

/// h = sum_{i + j <= kMaxDegree} c(i, j) x^i y^j, a user bivariate polynomial.
/// Coefficients outside the triangle i + j <= kMaxDegree must be zero.
struct PolynomialPath {
  static constexpr int kMaxDegree = 6;
  using Coefficients = Eigen::Matrix<double, kMaxDegree + 1, kMaxDegree + 1>;
  Coefficients c = Coefficients::Zero();  ///< c(i, j) multiplies x^i y^j
};

using PathShape = std::variant<CirclePath, LinePath, EllipsePath, PolynomialPath>;

/// A validated path shape with evaluation of h, gradient and Hessian.
class GeometricPath {
 public:
  /// Validates the shape (radius, semi-axes > 0, normal non-zero, coefficients finite and
  /// inside the degree triangle, polynomial not constant); throws std::invalid_argument.
  explicit GeometricPath(const PathShape& shape);

  PathEvaluation evaluate(const Eigen::Vector2d& p) const;

  const PathShape& shape() const { return shape_; }

 private:
  PathShape shape_;
};

}  // namespace plexus::algorithms
