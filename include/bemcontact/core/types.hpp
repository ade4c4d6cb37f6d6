#pragma once
// Scalar, index and small vector types shared by every layer.
#include <Eigen/Dense>
#include <cstddef>
#include <string>

namespace bemcontact {

using Index = std::ptrdiff_t;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor>;

// Analysis type of a 2D body (section II.3).
enum class AnalysisType { plane_strain, plane_stress, axisymmetric };

// Interpolation of u and p on an element (section II.5.2.1): same order for both.
// Quadratic elements (3 nodes) follow the exact geometry of their piece (line or arc).
enum class Interpolation { constant, linear, quadratic };

const char* to_string(AnalysisType type);
const char* to_string(Interpolation interpolation);
// "(x, y)" for messages that name a point.
std::string point_text(const Vec2& p);

// Isotropic linear-elastic material (I.5).
struct Material {
  double young_modulus = 0.0;  // E
  double poisson_ratio = 0.0;  // nu
  double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

// The Poisson ratio that enters the plane-strain kernels: nu for plane strain and
// axisymmetry, nu/(1+nu) for plane stress (section II.3.1). The shear modulus is unchanged.
double kernel_poisson_ratio(AnalysisType type, const Material& material);

}  // namespace bemcontact
