// Reference case of rough-surface contact: a rigid wavy profile on a large elastic block
// against Westergaard's periodic solution.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/reference/wavy_contact.hpp"
#include "bemcontact/validation/case_groups.hpp"

namespace bemcontact::validation {
namespace {

std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// The problem file of the case: a block [-W, W] x [-W, 0] (plane strain, clamped base)
// whose top holds a contact zone over `waves` wavelengths (|x| <= waves lambda / 2, the
// zone's ends under troughs), `per_wave` linear elements per wavelength, pressed by a rigid
// contour y = Delta (1 - cos(2 pi x / lambda)) (crests at x = k lambda touching the block)
// with the force P in three equal steps. The contour's points fall on the zone's nodes and
// between (20 per element), so the gap is exact at every pair.
std::string wavy_problem(double lambda, double delta, int waves, int per_wave, double W, double P) {
  const double half = 0.5 * waves * lambda;
  std::string points;
  const int count = waves * per_wave * 20;
  for (int k = 0; k <= count; ++k) {
    const double x = -half + waves * lambda * k / count;
    const double y = delta * (1.0 - std::cos(2.0 * std::numbers::pi * x / lambda));
    points += (k ? ", [" : "[") + shortest(x) + ", " + shortest(y) + "]";
  }
  const std::string w = shortest(W), h = shortest(half);
  return "title = \"wavy-contact\"\nanalysis = \"plane_strain\"\n"
         "[[body]]\nname = \"block\"\n[body.material]\nE = 1.0\nnu = 0.3\n"
         "[body.vertices]\nA = [-" + w + ", -" + w + "]\nB = [" + w + ", -" + w + "]\nC = [" + w + ", 0.0]\n"
         "D = [" + h + ", 0.0]\nE = [-" + h + ", 0.0]\nF = [-" + w + ", 0.0]\n"
         "[[body.boundary]]\nname = \"base\"\nfrom = \"A\"\nto = \"B\"\nelements = 16\nu1 = 0.0\nu2 = 0.0\n"
         "[[body.boundary]]\nname = \"right\"\nfrom = \"B\"\nto = \"C\"\nelements = 16\n"
         "[[body.boundary]]\nname = \"top right\"\nfrom = \"C\"\nto = \"D\"\nelements = 24\ngrading = 40.0\n"
         "refine = \"end\"\n"
         "[[body.boundary]]\nname = \"contact\"\nfrom = \"D\"\nto = \"E\"\nelements = " +
         std::to_string(waves * per_wave) +
         "\n"
         "[[body.boundary]]\nname = \"top left\"\nfrom = \"E\"\nto = \"F\"\nelements = 24\ngrading = 40.0\n"
         "refine = \"start\"\n"
         "[[body.boundary]]\nname = \"left\"\nfrom = \"F\"\nto = \"A\"\nelements = 16\n"
         "[[body]]\nname = \"wave\"\n[body.rigid]\nprofile = \"contour\"\npoints = [" + points + "]\n"
         "[[contact]]\nbody1 = \"block\"\nboundary1 = \"contact\"\nbody2 = \"wave\"\nnormal = \"body1\"\n"
         "[solver]\nincrements = 3\nrecord_steps = true\n"
         "[load]\nbody = \"wave\"\ncomponent = 2\nforce = " + shortest(-P) + "\n";
}

// The central crest's contact (the pairs with |x| <= lambda / 2): its mean pressure over the
// wavelength (the integral of the pairs' piecewise linear pressure) and its half-width a.
// a is fitted on the pressure profile as the Hertz cases fit theirs (contact_support.hpp):
// Westergaard's p^2 / cos^2(pi x / lambda) = K (sin^2(pi a / lambda) - sin^2(pi x / lambda))
// is linear in u = sin^2(pi x / lambda), so a least-squares line through the pairs in
// contact with |x| <= 0.8 x_last (x_last: the outermost pair in contact; the edge pairs, where
// a pair is partly open, are left out) gives sin^2(pi a / lambda) as its zero. The fit uses
// the profile's shape only: the mean pressure it is compared with comes from the integral.
struct Crest {
  double mean_pressure = 0.0, half_width = 0.0;
};
Crest central_crest(const std::vector<contact::PairResult>& all, double lambda) {
  std::vector<contact::PairResult> pairs;
  for (const auto& pair : all)
    if (std::abs(pair.coordinate) <= 0.5 * lambda * (1.0 + 1e-9)) pairs.push_back(pair);
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.coordinate < b.coordinate; });
  Crest crest;
  for (std::size_t k = 0; k + 1 < pairs.size(); ++k)
    crest.mean_pressure += 0.5 * (-pairs[k].p_n - pairs[k + 1].p_n) * (pairs[k + 1].coordinate - pairs[k].coordinate);
  crest.mean_pressure /= lambda;
  double last = 0.0;
  for (const auto& pair : pairs)
    if (pair.status != contact::PairStatus::open) last = std::max(last, std::abs(pair.coordinate));
  double n = 0.0, su = 0.0, sy = 0.0, suu = 0.0, suy = 0.0;
  for (const auto& pair : pairs) {
    if (pair.status == contact::PairStatus::open || std::abs(pair.coordinate) > 0.8 * last) continue;
    const double psi = std::numbers::pi * pair.coordinate / lambda;
    const double u = std::sin(psi) * std::sin(psi), y = pair.p_n * pair.p_n / (std::cos(psi) * std::cos(psi));
    n += 1.0, su += u, sy += y, suu += u * u, suy += u * y;
  }
  if (n < 3.0) return crest;  // too few pairs to fit: a = 0 fails the comparison visibly
  const double slope = (n * suy - su * sy) / (n * suu - su * su), intercept = (sy - slope * su) / n;
  crest.half_width = lambda / std::numbers::pi * std::asin(std::sqrt(std::clamp(-intercept / slope, 0.0, 1.0)));
  return crest;
}

// Westergaard's wavy surface [Westergaard1939], [Johnson1985, §13.2]: p_bar = p* sin^2(pi a /
// lambda) between the mean pressure over a wavelength and the contact half-width of its
// crest, for a rigid wave (amplitude Delta) on a half-plane, p* = pi E' Delta / lambda.
// The block is finite (W = 10 lambda wide each side, 10 lambda deep) and the profile has 7
// waves: on the scale of the block the wave is a flat rigid punch, whose uniform approach
// the block's compliance sets; the periodic part of the pressure decays within a wavelength
// of the surface and sees a half-plane. The crest's own relation between its mean pressure
// and its contact width does not depend on that uniform approach, so both are measured on
// the central crest (|x| <= lambda / 2, three wavelengths from the profile's ends). What
// remains of the finite profile is the slow variation of the mean pressure from crest to
// crest (a flat punch's 1/sqrt(L^2 - x^2): 0.5 % across the central wavelength for L = 3.5
// lambda), a second-order effect on the crest's own relation. The force P is applied in
// three steps: the central crest's p_bar / p* = sin^2(pi a / lambda) reaches 0.15, 0.28 and
// 0.41 (a / lambda = 0.126, 0.179, 0.223), the outer crests staying clear of their troughs.
std::vector<Record> run_wavy_contact(const Context& context) {
  std::vector<Record> records;
  const double lambda = 1.0, delta = 0.01, W = 10.0, P = 0.14;
  const int waves = 7;
  // Under refinement (max relative error of the mean pressure over the three loads, measured
  // here): 20 / 40 / 80 / 160 elements per wavelength: 28 / 5.5 / 0.32 / 0.14 %. At 20 the
  // smallest crest holds 5 pairs, too few for the fit; 160 takes 5 s and is left out. The
  // coarser meshes are reported, the error must fall at each refinement, and 80 is checked.
  double worst[3] = {0.0, 0.0, 0.0};
  const int meshes[3] = {20, 40, 80};
  for (int m = 0; m < 3; ++m) {
    const int per_wave = meshes[m];
    const auto file = io::parse_contact_problem(wavy_problem(lambda, delta, waves, per_wave, W, P), "wavy-contact");
    const reference::WavyContact exact{lambda, delta,
                                       reference::contact_modulus(file.problem.elastic(0).material, file.problem.analysis)};
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    const auto& steps = result.contacts.front().step_pairs;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const Crest crest = central_crest(steps[k], lambda);
      const double expected = exact.mean_pressure(crest.half_width);
      worst[m] = std::max(worst[m], std::abs(crest.mean_pressure / expected - 1.0));
      const std::size_t first = records.size();
      records.push_back(m == 2 ? compare_relative("mean_pressure", crest.mean_pressure, expected, 0.02)
                               : report_only("mean_pressure", crest.mean_pressure, expected));
      records.push_back(report_only("half_width", crest.half_width, exact.half_width(crest.mean_pressure)));
      records.push_back(report_value("pbar_over_pstar", crest.mean_pressure / exact.full_contact_pressure()));
      tag(records, first, "wavy-contact",
          {{"elements_per_wavelength", std::to_string(per_wave)}, {"load", std::to_string(k + 1) + "/3"}});
    }
  }
  const std::size_t first = records.size();
  records.push_back(require_at_least("error_ratio_20_to_40", worst[0] / worst[1], 1.0));
  records.push_back(require_at_least("error_ratio_40_to_80", worst[1] / worst[2], 1.0));
  tag(records, first, "wavy-contact", {{"refinement", "max error over the loads"}});
  return records;
}

}  // namespace

std::vector<Case> rough_cases() {
  return {
      {"wavy-contact", "Westergaard 1939", "rigid wavy profile on a large block: Westergaard's mean pressure against contact width",
       run_wavy_contact},
  };
}

}  // namespace bemcontact::validation
