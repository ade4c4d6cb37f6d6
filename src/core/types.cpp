#include "bemcontact/core/types.hpp"

#include <sstream>

namespace bemcontact {

const char* to_string(AnalysisType type) {
  switch (type) {
    case AnalysisType::plane_strain: return "plane_strain";
    case AnalysisType::plane_stress: return "plane_stress";
    case AnalysisType::axisymmetric: return "axisymmetric";
  }
  return "?";
}

const char* to_string(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::constant: return "constant";
    case Interpolation::linear: return "linear";
    case Interpolation::quadratic: return "quadratic";
  }
  return "?";
}

std::string point_text(const Vec2& p) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

double kernel_poisson_ratio(AnalysisType type, const Material& material) {
  const double nu = material.poisson_ratio;
  return type == AnalysisType::plane_stress ? nu / (1.0 + nu) : nu;
}

}  // namespace bemcontact
