#pragma once
// Values at any points of solved bodies, from their boundary solutions alone (`bemcontact
// probe`): the body or region that holds each point, and the displacement and stress there.
//   inside a body:  Somigliana's identity with the near-boundary treatment of interior_values;
//   on a boundary:  the boundary values interpolated at the closest point of the element;
//                   "on" means within round-off of an element, or outside its chord but no
//                   farther than the arc it replaces bulges beyond it (linear elements on
//                   arcs: a point on the true outer circle is on the boundary);
//   in the mirror image of a body drawn with symmetry lines: the values at its image
//   point, mapped back (u = S u', sigma = S sigma' S^T).
// A point on an interface belongs to every region it bounds, each with its own values.
#include <vector>

#include "bemcontact/bem/postprocess.hpp"

namespace bemcontact::bem {

struct ProbeRegion {
  const geometry::BoundaryMesh* mesh = nullptr;
  const BoundarySolution* solution = nullptr;  // displacements, tractions and nodal stresses
  AnalysisType analysis = AnalysisType::plane_strain;
  Material material;
  std::vector<double> bulge;  // per element: chord_bulges
  // Added inside to Somigliana's values: an elastoplastic region's cells (PlasticCellFields).
  DomainTerm domain_term;
};

// Per element of `mesh`: how far the piece's true curve lies outside the element's chord
// (the sagitta of a straight element on an arc that bulges outward; 0 otherwise).
std::vector<double> chord_bulges(const geometry::BoundaryMesh& mesh,
                                 const std::vector<geometry::BoundaryPiece>& pieces);

enum class PointPlace { outside, inside, boundary };

struct ProbeValue {
  Index point = -1;  // into the points
  int region = -1;   // into the regions
  Vec2 displacement = Vec2::Zero();
  StressTensor stress;
  bool on_boundary = false;
  bool mirrored = false;  // evaluated at the point's image across a symmetry line
};

struct ProbeResult {
  std::vector<ProbeValue> values;  // ordered by point, then region
  std::vector<Index> outside;      // the points that no region holds
};

// Where `point` lies with respect to the region as drawn (images not considered).
PointPlace place_in_region(const ProbeRegion& region, const Vec2& point);

ProbeResult probe_points(const std::vector<ProbeRegion>& regions, const std::vector<Vec2>& points,
                         const ProgressCallback& progress = {});

// The membrane and bending parts of the stress through a straight section of length t, the
// straight-line linearisation of pressure-vessel codes, each component on its own:
//   membrane = (1/t) int_0^t sigma ds,   bending = (6/t^2) int_0^t sigma (t/2 - s) ds,
// the bending part as at the section's start (s = 0; its opposite at the end), over samples
// at increasing s from 0 to t: Simpson's rule where they are equally spaced (the 3/8 rule
// closing an odd count), the piecewise-linear interpolant integrated exactly otherwise; a
// repeated s (an interface, each side's value) ends one piece and starts the next.
// The stress in the frame of the unit direction d: s11 along d, s22 across it (d turned a
// quarter counter-clockwise), s12 their shear, s33 as it is.
StressTensor stress_in_frame(const StressTensor& stress, const Vec2& d);

struct LinearisedStress {
  StressTensor membrane, bending;
};
LinearisedStress linearised_stress(const std::vector<double>& s, const std::vector<StressTensor>& stress);

}  // namespace bemcontact::bem
