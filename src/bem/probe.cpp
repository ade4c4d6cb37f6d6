#include "bemcontact/bem/probe.hpp"

#include <algorithm>
#include <cmath>

namespace bemcontact::bem {

std::vector<double> chord_bulges(const geometry::BoundaryMesh& mesh,
                                 const std::vector<geometry::BoundaryPiece>& pieces) {
  std::vector<double> bulges(mesh.elements.size(), 0.0);
  for (std::size_t k = 0; k < mesh.elements.size(); ++k) {
    const auto& element = mesh.elements[k];
    if (element.arc || element.piece < 0 || element.piece >= static_cast<int>(pieces.size())) continue;
    const auto& piece = pieces[element.piece];
    if (piece.shape != geometry::PieceShape::arc) continue;
    // The arc leaves the chord on the side away from its centre, by R - |midpoint - centre|.
    const Vec2 middle = 0.5 * (element.start + element.end) - piece.center;
    if (middle.dot(element.normal) > 0.0) bulges[k] = std::max(0.0, geometry::arc_radius(piece) - middle.norm());
  }
  return bulges;
}

PointPlace place_in_region(const ProbeRegion& region, const Vec2& point) {
  const auto& mesh = *region.mesh;
  const double round_off = 1e-9 * mesh.scale;
  const auto projection = project_on_boundary(mesh, point);
  if (projection.element < 0) return PointPlace::outside;
  if (projection.distance <= round_off) return PointPlace::boundary;
  if (point_inside(mesh, point, round_off)) return PointPlace::inside;
  const bool has_bulge = projection.element < static_cast<Index>(region.bulge.size());
  const double bulge = has_bulge ? region.bulge[projection.element] : 0.0;
  return projection.distance <= bulge + round_off ? PointPlace::boundary : PointPlace::outside;
}

namespace {

// Where a region takes a point's values: at the point, or at its image across a symmetry line.
struct Placement {
  PointPlace place = PointPlace::outside;
  Vec2 evaluated = Vec2::Zero();
  int image = -1;  // into mesh.images; -1: the point itself
};

Placement placement(const ProbeRegion& region, const Vec2& point) {
  const PointPlace direct = place_in_region(region, point);
  if (direct != PointPlace::outside) return {direct, point, -1};
  const auto& images = region.mesh->images;
  for (std::size_t k = 0; k < images.size(); ++k) {
    // Reflections and the half-turn are their own inverses: the point is the image of this one.
    const Vec2 image = images[k].apply(point);
    const PointPlace place = place_in_region(region, image);
    if (place != PointPlace::outside) return {place, image, static_cast<int>(k)};
  }
  return {};
}

// The element's interpolation of the nodal values at the point's closest boundary point.
void boundary_values(const geometry::BoundaryMesh& mesh, const BoundarySolution& solution, const Vec2& point,
                     ProbeValue& value) {
  const auto projection = project_on_boundary(mesh, point);
  const auto& element = mesh.elements[projection.element];
  value.displacement = interpolate_on_element(element, solution.displacement, projection.fraction);
  value.stress = StressTensor{};
  for (int a = 0; a < element.node_count; ++a) {
    const double w = element.shape(a, projection.fraction);
    const StressTensor& s = solution.stress[element.nodes[a]];
    value.stress.s11 += w * s.s11;
    value.stress.s22 += w * s.s22;
    value.stress.s12 += w * s.s12;
    value.stress.s33 += w * s.s33;
  }
}

// Values at an image point carried back to the point: u = S u', sigma = S sigma' S^T.
void map_back(const geometry::ImageMap& image, ProbeValue& value) {
  const Mat2& S = image.matrix;
  value.displacement = S * value.displacement;
  Mat2 sigma;
  sigma << value.stress.s11, value.stress.s12, value.stress.s12, value.stress.s22;
  const Mat2 mapped = S * sigma * S.transpose();
  value.stress.s11 = mapped(0, 0);
  value.stress.s22 = mapped(1, 1);
  value.stress.s12 = 0.5 * (mapped(0, 1) + mapped(1, 0));
}

// The values of the points that region r holds, in the order of the points.
std::vector<ProbeValue> region_values(const ProbeRegion& region, int r, const std::vector<Vec2>& points,
                                      const ProgressCallback& progress) {
  const Index m = static_cast<Index>(points.size());
  std::vector<Placement> placements(m);
#pragma omp parallel for schedule(dynamic, 16)
  for (Index k = 0; k < m; ++k) placements[k] = placement(region, points[k]);

  std::vector<ProbeValue> values;
  std::vector<Vec2> inside;
  std::vector<std::size_t> inside_value;
  for (Index k = 0; k < m; ++k) {
    const Placement& p = placements[k];
    if (p.place == PointPlace::outside) continue;
    ProbeValue value;
    value.point = k;
    value.region = r;
    value.mirrored = p.image >= 0;
    value.on_boundary = p.place == PointPlace::boundary;
    if (value.on_boundary) {
      boundary_values(*region.mesh, *region.solution, p.evaluated, value);
    } else {
      inside.push_back(p.evaluated);
      inside_value.push_back(values.size());
    }
    values.push_back(value);
  }
  if (!inside.empty()) {
    const ElementIntegrator integrator(region.analysis, region.material);
    const auto interior = interior_values(*region.mesh, integrator, *region.solution, inside, progress, region.domain_term);
    for (std::size_t i = 0; i < inside.size(); ++i) {
      values[inside_value[i]].displacement = interior.displacement[i];
      values[inside_value[i]].stress = interior.stress[i];
    }
  }
  for (auto& value : values)
    if (value.mirrored) map_back(region.mesh->images[placements[value.point].image], value);
  return values;
}

}  // namespace

ProbeResult probe_points(const std::vector<ProbeRegion>& regions, const std::vector<Vec2>& points,
                         const ProgressCallback& progress) {
  std::vector<ProbeValue> all;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    auto values = region_values(regions[r], static_cast<int>(r), points, progress);
    all.insert(all.end(), values.begin(), values.end());
  }
  std::stable_sort(all.begin(), all.end(), [](const ProbeValue& a, const ProbeValue& b) { return a.point < b.point; });
  ProbeResult result;
  std::vector<bool> held(points.size(), false);
  for (const auto& value : all) held[value.point] = true;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!held[k]) result.outside.push_back(static_cast<Index>(k));
  result.values = std::move(all);
  return result;
}

StressTensor stress_in_frame(const StressTensor& stress, const Vec2& d) {
  Mat2 q;
  q << d, Vec2(-d.y(), d.x());
  Mat2 sigma;
  sigma << stress.s11, stress.s12, stress.s12, stress.s22;
  const Mat2 local = q.transpose() * sigma * q;
  return {local(0, 0), local(1, 1), 0.5 * (local(0, 1) + local(1, 0)), stress.s33};
}

namespace {

// Weights of the samples s[first..last] (increasing) in the integrals of sigma and of
// sigma (t/2 - s'), s' = s - s[0]: Simpson's rule when they are equally spaced (the 3/8 rule
// on the last three intervals of an odd count), exact for sigma up to quadratic; otherwise
// sigma's piecewise-linear interpolant integrated exactly.
void add_piece_weights(const std::vector<double>& s, std::size_t first, std::size_t last, std::vector<double>& membrane,
                       std::vector<double>& bending) {
  const double t = s.back() - s.front();
  const auto lever = [&](std::size_t j) { return 0.5 * t - (s[j] - s.front()); };
  const std::size_t intervals = last - first;
  const double h = (s[last] - s[first]) / static_cast<double>(intervals);
  bool uniform = intervals >= 2;
  for (std::size_t k = first + 1; k <= last && uniform; ++k)
    uniform = std::abs(s[k] - s[k - 1] - h) <= 1e-9 * std::abs(h) * static_cast<double>(intervals);
  if (!uniform) {
    for (std::size_t k = first + 1; k <= last; ++k) {
      const double step = s[k] - s[k - 1], w0 = lever(k - 1), w1 = lever(k);
      membrane[k - 1] += 0.5 * step;
      membrane[k] += 0.5 * step;
      bending[k - 1] += step / 6.0 * (2.0 * w0 + w1);
      bending[k] += step / 6.0 * (w0 + 2.0 * w1);
    }
    return;
  }
  std::vector<double> w(intervals + 1, 0.0);
  const std::size_t simpson = intervals % 2 == 0 ? intervals : intervals - 3;
  for (std::size_t k = 0; k + 2 <= simpson; k += 2) {
    w[k] += h / 3.0;
    w[k + 1] += 4.0 * h / 3.0;
    w[k + 2] += h / 3.0;
  }
  if (simpson != intervals)
    for (const auto& [offset, weight] : {std::pair{0, 1.0}, std::pair{1, 3.0}, std::pair{2, 3.0}, std::pair{3, 1.0}})
      w[simpson + offset] += 3.0 * h / 8.0 * weight;
  for (std::size_t k = 0; k <= intervals; ++k) {
    membrane[first + k] += w[k];
    bending[first + k] += w[k] * lever(first + k);
  }
}

}  // namespace

LinearisedStress linearised_stress(const std::vector<double>& s, const std::vector<StressTensor>& stress) {
  LinearisedStress result;
  if (s.size() < 2 || !(s.back() > s.front())) return result;
  // Pieces between repeated abscissae (an interface: each side's values end its piece).
  std::vector<double> membrane(s.size(), 0.0), bending(s.size(), 0.0);
  std::size_t first = 0;
  for (std::size_t k = 1; k <= s.size(); ++k)
    if (k == s.size() || s[k] == s[k - 1]) {
      if (k - 1 > first) add_piece_weights(s, first, k - 1, membrane, bending);
      first = k;
    }
  const double t = s.back() - s.front();
  const auto add = [](StressTensor& sum, const StressTensor& value, double weight) {
    sum.s11 += weight * value.s11;
    sum.s22 += weight * value.s22;
    sum.s12 += weight * value.s12;
    sum.s33 += weight * value.s33;
  };
  for (std::size_t j = 0; j < s.size(); ++j) {
    add(result.membrane, stress[j], membrane[j] / t);
    add(result.bending, stress[j], bending[j] * 6.0 / (t * t));
  }
  return result;
}

}  // namespace bemcontact::bem
