#pragma once
// Helpers shared by the contact reference cases.
#include <vector>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/reference/flat_punch.hpp"
#include "bemcontact/validation/validation.hpp"

namespace bemcontact::validation {

// Hertz's profile p^2 = p0^2 (1 - r^2/a^2) (point or line contact) is linear in r^2: a and
// p0 fitted by least squares on the pairs in contact with 0 < r < window. The pair on the
// axis is left out: collocation at r = 0 gives it a value a few per cent high.
struct HertzFit {
  double a = 0.0;
  double p0 = 0.0;
};
HertzFit fit_hertz_profile(const std::vector<contact::PairResult>& pairs, double window);

// The same profile about a centre x_c that is not on the axis (a contact shifted by the
// bodies' rotation): p^2 = c0 + c1 x + c2 x^2 fitted on the pairs in contact within 0.8 of
// the half-width of their extent [first, last] (ContactSummary::contact_start, _end)
// about its middle; x_c = -c1 / (2 c2), p0^2 = p^2(x_c), a^2 = -p0^2 / c2.
struct CentredHertzFit {
  HertzFit fit;
  double centre = 0.0;
};
CentredHertzFit fit_hertz_profile_free_centre(const std::vector<contact::PairResult>& pairs, double first,
                                              double last);

// Largest |difference| of p_n and p_t between two solutions of one problem (the same
// pairs), over the first's peak pressure: Newton against the thesis algorithm.
double algorithm_difference(const contact::ContactResult& a, const contact::ContactResult& b);

// Newton and the thesis' algorithm on the same equal steps (adaptive stepping off): their
// solutions and algorithm_difference of the two.
struct AlgorithmComparison {
  contact::ContactResult newton, thesis;
  double difference = 0.0;
};
AlgorithmComparison compare_algorithms(const Context& context, const contact::ContactProblem& problem);

// A bundled contact example, with parameter overrides.
io::ContactFile load_contact_example(const Context& context, const std::string& file,
                                     const io::ParameterOverrides& overrides = {});

// Largest relative error of the pressure against a rigid flat punch's P / (pi sqrt(a^2 -
// x^2)) over the pairs with |x| <= 0.8a (the edges are singular).
double flat_punch_max_error(const std::vector<contact::PairResult>& pairs, const reference::FlatPunchPlane& exact);

}  // namespace bemcontact::validation
