#pragma once
// Contours of rigid indenters (ContactProblem's RigidBody): line and arc pieces with the
// body on the left, so that their outward normal is the indenter's. Analytic profiles are
// exact (the sphere's arcs are arcs); a polyline gives any other shape.
#include <string>
#include <vector>

#include "bemcontact/contact/rough_profile.hpp"
#include "bemcontact/geometry/boundary.hpp"

namespace bemcontact::contact {

struct ProfileShape {
  std::string profile;           // "sphere" / "cylinder", "flat", "cone", "contour", "rough"
  Vec2 center = Vec2::Zero();    // sphere, cylinder: centre; flat: middle of the face; cone: apex;
                                 // rough: the middle of the mean line
  double radius = 0.0;           // sphere, cylinder
  double half_width = 0.0;       // flat: half-width a of the flat face
  double edge_radius = 0.0;      // flat: radius of the rounded edges (0: sharp)
  double half_angle = 0.0;       // cone: half-angle theta in radians (0 < theta < pi / 2)
  double height = 1.0;           // flat, cone: how far the sides rise above the face or apex
  std::vector<Vec2> points;      // contour: polyline, body on the left
  RoughProfileSpec rough;        // rough: the profile's spectrum and samples
};

// The pieces of the profile; the flat punch and the cone face down (-y), their sides rise
// by `height`. A rough profile faces down too: a polyline through x_k = cx - L/2 + k L/(N-1),
// y_k = cy - h_k (rough_heights: its peaks, h > 0, reach down toward the elastic body). Throws InputError-free GeometryError for a degenerate shape.
std::vector<geometry::BoundaryPiece> rigid_contour(const ProfileShape& shape);

}  // namespace bemcontact::contact
