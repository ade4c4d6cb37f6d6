#pragma once
// Integration of the plane Kelvin kernels over an element. Straight elements with
// constant or linear shape functions: in closed form (Annex C), exact for any source
// position, including the singular element and sources close to the element. Quadratic
// (and curved) elements: Gauss quadrature (plane_element_quadrature.cpp). The two entry
// points below choose.
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/integration/element_influence.hpp"

namespace bemcontact::integration {

// source_node: index a of the element node the source coincides with, or -1.
ElementInfluence integrate_plane_element(const kernels::KelvinPlane& kelvin, const Vec2& source,
                                         const geometry::BoundaryElement& element,
                                         int source_node);

// Interior-stress kernels D and S over the element for a point off the element.
ElementStressInfluence integrate_plane_element_stress(const kernels::KelvinPlane& kelvin,
                                                      const Vec2& point,
                                                      const geometry::BoundaryElement& element);

// The quadrature versions, for any element (tests compare them with the closed forms).
ElementInfluence integrate_plane_element_by_quadrature(const kernels::KelvinPlane& kelvin, const Vec2& source,
                                                       const geometry::BoundaryElement& element, int source_node);
ElementStressInfluence integrate_plane_element_stress_by_quadrature(const kernels::KelvinPlane& kelvin,
                                                                    const Vec2& point,
                                                                    const geometry::BoundaryElement& element);

}  // namespace bemcontact::integration
