// A law per contact: two independent rigid flat punches on two blocks, one contact
// frictionless and the other with friction, solved as one problem, against each pair solved
// alone with its own law (an independent computation: the condensed problem of the pair
// of bodies is the same block). Both algorithms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"

namespace bemcontact::contact {
namespace {

// Block `k` (x offset 100 k) under rigid punch `k`; `law` is the [[contact]] table's law
// keys ("" for the problem's default, frictionless).
std::string punch_on_block(int k, const std::string& law) {
  const std::string n = std::to_string(k), x = std::to_string(100 * k);
  const auto at = [k](int dx) { return std::to_string(100 * k + dx); };
  return "[[body]]\nname = \"block" + n + "\"\n[body.material]\nE = 1.0\nnu = 0.3\n[body.vertices]\n" +
         "A = [" + at(-20) + ", -20.0]\nB = [" + at(20) + ", -20.0]\nC = [" + at(20) + ", 0.0]\n" +
         "D = [" + at(1) + ", 0.0]\nE = [" + at(-1) + ", 0.0]\nF = [" + at(-20) + ", 0.0]\n" +
         "[[body.boundary]]\nname = \"base\"\nfrom = \"A\"\nto = \"B\"\nelements = 10\nu1 = 0.0\nu2 = 0.0\n"
         "[[body.boundary]]\nname = \"right\"\nfrom = \"B\"\nto = \"C\"\nelements = 10\n"
         "[[body.boundary]]\nname = \"top right\"\nfrom = \"C\"\nto = \"D\"\nelements = 20\ngrading = 40.0\n"
         "refine = \"end\"\n"
         "[[body.boundary]]\nname = \"contact\"\nfrom = \"D\"\nto = \"E\"\nelements = 24\n"
         "[[body.boundary]]\nname = \"top left\"\nfrom = \"E\"\nto = \"F\"\nelements = 20\ngrading = 40.0\n"
         "refine = \"start\"\n"
         "[[body.boundary]]\nname = \"left\"\nfrom = \"F\"\nto = \"A\"\nelements = 10\n"
         "[[body]]\nname = \"punch" + n + "\"\n[body.rigid]\nprofile = \"flat\"\ncenter = [" + x +
         ", 0.0]\nhalf_width = 1.0\n"
         "[[contact]]\nname = \"contact" + n + "\"\nbody1 = \"block" + n + "\"\nboundary1 = \"contact\"\nbody2 = \"punch" +
         n + "\"\nnormal = \"body1\"\n" + law +
         "[[load]]\nbody = \"punch" + n + "\"\ncomponent = 2\nforce = -0.01\n";
}

std::string problem_text(const std::string& bodies, const std::string& algorithm) {
  return "title = \"punches\"\nanalysis = \"plane_strain\"\n" + bodies +
         "[solver]\nalgorithm = \"" + algorithm + "\"\nincrements = 4\nadaptive = false\n";
}

std::string exact_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

double largest(const std::vector<PairResult>& pairs, bool shear) {
  double m = 0.0;
  for (const auto& p : pairs) m = std::max(m, std::abs(shear ? p.p_t : p.p_n));
  return m;
}

}  // namespace

TEST(ContactLaws, EachContactFollowsItsOwnFriction) {
  const std::string frictional = "friction = 0.5\n";
  // Tolerances: Newton stops at a complementarity residual of 1e-10; the thesis algorithm's
  // threshold iteration at a relative change of sqrt(xi) = 1e-4 over all pairs together,
  // hence 10 times that between the joint and the separate solves.
  for (const auto& [algorithm, tolerance] : {std::pair<std::string, double>{"newton", 1e-7}, {"thesis", 1e-3}}) {
    const auto joint = io::parse_contact_problem(problem_text(punch_on_block(0, "") + punch_on_block(1, frictional), algorithm),
                                                 "joint.toml");
    ASSERT_EQ(joint.problem.contacts.size(), 2u);
    EXPECT_DOUBLE_EQ(joint.problem.contacts[0].law.friction, 0.0);
    EXPECT_DOUBLE_EQ(joint.problem.contacts[1].law.friction, 0.5);
    const auto both = solve_contact(joint.problem);
    const auto alone0 = solve_contact(io::parse_contact_problem(problem_text(punch_on_block(0, ""), algorithm), "a.toml").problem);
    const auto alone1 =
        solve_contact(io::parse_contact_problem(problem_text(punch_on_block(1, frictional), algorithm), "b.toml").problem);
    const ContactResult* alone[2] = {&alone0, &alone1};
    for (int c = 0; c < 2; ++c) {
      const auto& pairs = both.contacts[c].pairs;
      const auto& reference = alone[c]->contacts[0].pairs;
      ASSERT_EQ(pairs.size(), reference.size());
      const double scale = largest(reference, false);
      double difference = 0.0;
      for (std::size_t i = 0; i < pairs.size(); ++i)
        difference = std::max({difference, std::abs(pairs[i].p_n - reference[i].p_n),
                               std::abs(pairs[i].p_t - reference[i].p_t)});
      std::printf("%s contact %d: largest difference %.2e of the peak pressure, shear %.3g of it\n", algorithm.c_str(), c,
                  difference / scale, largest(pairs, true) / largest(pairs, false));
      EXPECT_LT(difference, tolerance * scale) << algorithm << " contact " << c;
    }
    // The frictional punch holds the block's surface back (it slips at the edges, where the
    // shear reaches 0.5 of the peak pressure); the frictionless one carries no shear.
    EXPECT_EQ(largest(both.contacts[0].pairs, true), 0.0) << algorithm;
    EXPECT_GT(largest(both.contacts[1].pairs, true), 0.01 * largest(both.contacts[1].pairs, false)) << algorithm;
  }
}

// Every contact holds its law, the defaults applied by the reader (one place per law: the
// solvers and writers read it there); different tangential couplings are refused with the
// contact's line.
TEST(ContactLaws, EachContactHoldsItsLawAndCouplingsMustAgree) {
  const auto same = io::parse_contact_problem(
      problem_text(punch_on_block(0, "friction = 0.2\n") + punch_on_block(1, "kind = \"bilateral\"\n"), "newton"),
      "same.toml");
  EXPECT_EQ(same.problem.contacts[0].law, (ContactLaw{ContactKind::unilateral, 0.2}));
  EXPECT_EQ(same.problem.contacts[1].law, (ContactLaw{ContactKind::bilateral, 0.0}));
  try {
    io::parse_contact_problem(problem_text(punch_on_block(0, "friction = 0.2\n") +
                                               punch_on_block(1, "friction = 0.2\ncoupling = false\n"),
                                           "newton"),
                              "coupling.toml");
    FAIL() << "different couplings accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling"), std::string::npos) << e.what();
  }
}

}  // namespace bemcontact::contact

namespace bemcontact::contact {

// A moment on a rigid flat punch (component 3 of a load): both algorithms give the same
// pressure and rotation (the closed form is checked by `validate rigid-punch`), and that
// rotation prescribed gives the same pressure; a moment on an elastic body or in
// axisymmetry, a prescribed rotation with a moment, too large or in axisymmetry are refused.
TEST(RigidRotation, BothAlgorithmsAgreeAndBadMomentsAreRefused) {
  const std::string moment = "[[load]]\nname = \"moment\"\nbody = \"punch0\"\ncomponent = 3\nforce = 0.0025\n";
  const auto newton = solve_contact(io::parse_contact_problem(problem_text(punch_on_block(0, "") + moment, "newton"), "m.toml").problem);
  const auto thesis = solve_contact(io::parse_contact_problem(problem_text(punch_on_block(0, "") + moment, "thesis"), "m.toml").problem);
  ASSERT_EQ(newton.records.back().motions.size(), 2);
  const double rotation = newton.records.back().motions[1];
  EXPECT_GT(rotation, 0.0);  // counter-clockwise moment, counter-clockwise rotation
  EXPECT_NEAR(thesis.records.back().motions[1] / rotation, 1.0, 1e-3);
  // The pressure is larger on the side the moment pushes down (-x).
  const auto [left, right] = std::minmax_element(newton.pairs.begin(), newton.pairs.end(),
                                                 [](const PairResult& a, const PairResult& b) { return a.coordinate < b.coordinate; });
  EXPECT_GT(-left->p_n, -right->p_n);
  const auto refused = [](const std::string& text, const std::string& fragment) {
    try {
      io::parse_contact_problem(text, "bad.toml");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused(problem_text(punch_on_block(0, "") +
                           "[[load]]\nbody = \"block0\"\nboundary = \"right\"\ncomponent = 3\nforce = 1.0\n",
                       "newton"),
          "is elastic");
  std::ifstream in(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_rigid_sphere.toml");
  std::string ball((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ball.replace(ball.find("[load]"), 6, "[[load]]");
  refused(ball + "\n[[load]]\nbody = \"ball\"\ncomponent = 3\nforce = 1.0\n", "axisymmetry");
  // A prescribed rotation: with a moment on the same body, too large, in axisymmetry.
  const auto turned = [](const std::string& rotation) {
    std::string text = punch_on_block(0, "");
    text.replace(text.find("half_width = 1.0\n"), 17, "half_width = 1.0\nrotation = " + rotation + "\n");
    return text;
  };
  refused(problem_text(turned("0.001") + moment, "newton"), "prescribed rotation");
  refused(problem_text(turned("0.5"), "newton"), "-0.1 <= rotation <= 0.1");
  std::string turned_ball = ball;
  turned_ball.replace(turned_ball.find("radius = \"R\""), 12, "radius = \"R\"\nrotation = 0.001");
  refused(turned_ball, "axisymmetry");
  // Prescribed, it turns the punch as the moment did: the same motion from either side.
  const auto prescribed = solve_contact(
      io::parse_contact_problem(problem_text(turned(exact_text(rotation)), "newton"), "r.toml").problem);
  const auto [low, high] = std::minmax_element(prescribed.pairs.begin(), prescribed.pairs.end(),
                                               [](const PairResult& a, const PairResult& b) { return a.coordinate < b.coordinate; });
  EXPECT_NEAR(low->p_n / left->p_n, 1.0, 1e-8);  // Newton stops at a residual of 1e-10
  EXPECT_NEAR(high->p_n / right->p_n, 1.0, 1e-8);
}

}  // namespace bemcontact::contact
