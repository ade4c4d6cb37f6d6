#pragma once
// Symmetry lines: a body drawn as the half (or quarter) of one symmetric about straight
// lines. A boundary marked `symmetry` carries no elements; the other part of the body is its
// mirror image, and every element acts twice (four times for two lines): as itself and as its
// images, whose displacements and tractions are the element's own mapped by the image's
// matrix (u' = S u). The discrete problem is then exactly that of the whole symmetric body
// meshed symmetrically, with half the unknowns, and nothing is lost where the line meets the
// boundary (a roller boundary u_n = 0, t_t = 0 is the same problem continuously, but its own
// discretisation error there grows under refinement next to a contact: docs/corners.md).
#include <string>
#include <vector>

#include "bemcontact/core/types.hpp"

namespace bemcontact::geometry {

struct BoundaryElement;
struct BoundaryPiece;

// x -> matrix x + offset: a reflection across a line (det -1), or for two perpendicular
// lines also the half-turn about their crossing (det +1).
struct ImageMap {
  Mat2 matrix = Mat2::Identity();
  Vec2 offset = Vec2::Zero();
  Vec2 apply(const Vec2& x) const { return matrix * x + offset; }
  bool reverses() const { return matrix.determinant() < 0.0; }
};

// The images of a body whose symmetry pieces are `pieces[k].symmetry`: none, the reflection
// across one line, or the two reflections and the half-turn of two perpendicular lines.
// Throws GeometryError (naming the boundaries) for a symmetry piece that is not straight, for
// lines that are neither one nor two perpendicular ones, for a body that does not lie on one
// side of each line, and in axisymmetry for a line that is not perpendicular to the axis
// (z = const).
std::vector<ImageMap> symmetry_images(const std::vector<BoundaryPiece>& pieces, bool axisymmetric);

// The number of distinct symmetry lines behind a body's images (0, 1 or 2).
inline int symmetry_line_count(const std::vector<ImageMap>& images) { return images.size() == 3 ? 2 : static_cast<int>(images.size()); }

// The image of an element: its geometry mapped, traversed so that the image body lies on its
// left (a reflection reverses it), node a of the image standing at the image of node a (its
// fraction 1 - f when reversed), node indices kept.
BoundaryElement image_element(const BoundaryElement& element, const ImageMap& image);

}  // namespace bemcontact::geometry
