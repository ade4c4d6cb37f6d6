// Bad multi-subdomain input -> a message naming the file, the line, the key or the
// interface and node at fault.
#include <gtest/gtest.h>

#include "bemcontact/dd/solver.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"

namespace bemcontact::io {
namespace {

// Two unit squares stacked, glued along y = 1; `lower_mid` / `upper_mid` are inserted in
// the interface boundaries, `extra` at the top level.
std::string two_squares(const std::string& lower_mid = "elements = 4\ninterface = \"mid\"\n",
                        const std::string& upper_mid = "elements = 4\ninterface = \"mid\"\n",
                        const std::string& extra = "") {
  return "analysis = \"plane_strain\"\n" + extra +
         "[vertices]\nA = [0.0, 0.0]\nB = [1.0, 0.0]\nC = [1.0, 1.0]\nD = [0.0, 1.0]\nE = [1.0, 2.0]\nF = [0.0, 2.0]\n"
         "[[subdomain]]\nname = \"lower\"\n[subdomain.material]\nE = 1.0\nnu = 0.3\n"
         "[[subdomain.boundary]]\nfrom = \"A\"\nto = \"B\"\nelements = 4\nu1 = 0.0\nu2 = 0.0\n"
         "[[subdomain.boundary]]\nfrom = \"B\"\nto = \"C\"\nelements = 4\n"
         "[[subdomain.boundary]]\nname = \"mid\"\nfrom = \"C\"\nto = \"D\"\n" + lower_mid +
         "[[subdomain.boundary]]\nfrom = \"D\"\nto = \"A\"\nelements = 4\n"
         "[[subdomain]]\nname = \"upper\"\n[subdomain.material]\nE = 2.0\nnu = 0.3\n"
         "[[subdomain.boundary]]\nname = \"mid\"\nfrom = \"D\"\nto = \"C\"\n" + upper_mid +
         "[[subdomain.boundary]]\nfrom = \"C\"\nto = \"E\"\nelements = 4\n"
         "[[subdomain.boundary]]\nfrom = \"E\"\nto = \"F\"\nelements = 4\nt2 = 1.0\n"
         "[[subdomain.boundary]]\nfrom = \"F\"\nto = \"D\"\nelements = 4\n";
}

template <typename Error, typename F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

void expect_contains(const std::string& message, const std::vector<std::string>& parts) {
  for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(DdErrors, ValidFileSolvesAndGluesTheSquares) {
  const auto file = parse_decomposition(two_squares(), "ok.toml");
  const auto result = dd::solve_decomposition(file.problem);
  ASSERT_TRUE(result.converged()) << result.gmres.message;
  EXPECT_LT(result.jumps[0].jump_u, 1e-7);
  EXPECT_LT(result.jumps[0].jump_p, 1e-7);
}

TEST(DdErrors, NonMatchingInterfaceNamesTheInterfaceAndTheNode) {
  const auto file = parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n",
                                                    "elements = 5\ninterface = \"mid\"\n"),
                                        "mismatch.toml");
  const std::string message = message_of<InputError>([&] { dd::solve_decomposition(file.problem); });
  expect_contains(message, {"mismatch.toml", "interface 'mid' does not match", "subdomain 'lower'", "node ",
                            "no facing node in subdomain 'upper'", "same elements"});
}

TEST(DdErrors, InterfaceListedOnce) {
  const auto file = parse_decomposition(
      two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\ninterface = \"middle\"\n"), "once.toml");
  const std::string message = message_of<InputError>([&] { dd::solve_decomposition(file.problem); });
  expect_contains(message, {"once.toml:", "interface 'mid' is listed only by subdomain 'lower'"});
}

TEST(DdErrors, InterfaceWithACondition) {
  const std::string message = message_of<InputError>([] {
    parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\nu2 = 0.0\n"), "cond.toml");
  });
  expect_contains(message, {"cond.toml:", "subdomain[1].boundary[3].u2", "takes no condition"});
}

TEST(DdErrors, BadDecompositionOptions) {
  std::string message = message_of<InputError>(
      [] { parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\ninterface = \"mid\"\n",
                                           "[decomposition]\nmethod = \"schur\"\n"), "m.toml"); });
  expect_contains(message, {"m.toml:3", "decomposition.method", "mixed"});
  message = message_of<InputError>(
      [] { parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\ninterface = \"mid\"\n",
                                           "[decomposition]\nrestart = 0\n"), "r.toml"); });
  expect_contains(message, {"r.toml:3", "decomposition.restart", ">= 1"});
  message = message_of<InputError>(
      [] { parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\ninterface = \"mid\"\n",
                                           "[decomposition]\ntolerence = 1e-6\n"), "t.toml"); });
  expect_contains(message, {"t.toml:3", "tolerence", "Did you mean 'tolerance'"});
  message = message_of<InputError>(
      [] { parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\ninterface = \"mid\"\n",
                                           "[decomposition]\nmethod = \"mixed\"\npreconditioner = \"balancing\"\n"),
                               "p.toml"); });
  expect_contains(message, {"p.toml:4", "decomposition.preconditioner", "method = \"conforming\"",
                            "preconditioner = \"none\""});
  message = message_of<InputError>(
      [] { parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\ninterface = \"mid\"\n",
                                           "[decomposition]\nexplicit_operators = false\n"),
                               "e.toml"); });
  expect_contains(message, {"e.toml:3", "decomposition.explicit_operators", "balancing"});
}

// The default: conforming unknowns with the balancing preconditioner; another method
// without a preconditioner key is unpreconditioned.
TEST(DdErrors, DefaultPreconditionerFollowsTheMethod) {
  const std::string pieces = "elements = 4\ninterface = \"mid\"\n";
  auto file = parse_decomposition(two_squares(pieces, pieces), "d.toml");
  EXPECT_EQ(file.problem.options.method, dd::InterfaceMethod::conforming);
  EXPECT_EQ(file.problem.options.preconditioner, dd::InterfacePreconditioner::balancing);
  file = parse_decomposition(two_squares(pieces, pieces, "[decomposition]\nmethod = \"mixed\"\n"), "d.toml");
  EXPECT_EQ(file.problem.options.preconditioner, dd::InterfacePreconditioner::none);
}

TEST(DdErrors, BodyKeysAtTheTopLevel) {
  const std::string message =
      message_of<InputError>([] { parse_decomposition("analysis = \"plane_strain\"\n[material]\nE = 1.0\nnu = 0.3\n"
                                                      "[[subdomain]]\nname = \"a\"\n", "top.toml"); });
  expect_contains(message, {"top.toml:2", "'material' belongs in each [[subdomain]]"});
}

TEST(DdErrors, UnknownBoundaryKeySuggestsInterface) {
  const std::string message = message_of<InputError>(
      [] { parse_decomposition(two_squares("elements = 4\ninterfce = \"mid\"\n"), "k.toml"); });
  expect_contains(message, {"k.toml:", "interfce", "Did you mean 'interface'"});
}

TEST(DdErrors, FloatingSubdomainUnderTheHybridMethodNamesIt) {
  const auto file = parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n",
                                                    "elements = 4\ninterface = \"mid\"\n",
                                                    "[decomposition]\nmethod = \"hybrid\"\n"),
                                        "h.toml");
  const std::string message = message_of<SolverError>([&] { dd::solve_decomposition(file.problem); });
  expect_contains(message, {"subdomain 'upper' is free to move", "hybrid", "mixed"});
}

TEST(DdErrors, SubdomainWithoutInterface) {
  const std::string message = message_of<InputError>([] {
    parse_decomposition(two_squares("elements = 4\ninterface = \"mid\"\n", "elements = 4\nt2 = 0.0\n"), "no.toml");
  });
  expect_contains(message, {"no.toml:", "subdomain 'upper' has no boundary with interface"});
}

TEST(DdErrors, DuplicateSubdomainName) {
  std::string text = two_squares();
  text.replace(text.find("name = \"upper\""), 14, "name = \"lower\"");
  const std::string message = message_of<InputError>([&] { parse_decomposition(text, "dup.toml"); });
  expect_contains(message, {"dup.toml:", "subdomain[2].name", "already used"});
}

TEST(DdErrors, SubdomainNamesThatGiveOneFileNameOrAreTooLong) {
  std::string text = two_squares();
  text.replace(text.find("name = \"lower\""), 14, "name = \"a b\"");
  text.replace(text.find("name = \"upper\""), 14, "name = \"a_b\"");
  expect_contains(message_of<InputError>([&] { parse_decomposition(text, "same.toml"); }),
                  {"same.toml:", "subdomain[2].name", "subdomain 'a_b' and the subdomain at line", "files of one name"});
  text = two_squares();
  text.replace(text.find("name = \"lower\""), 14, "name = \"" + std::string(3000, 'L') + "\"");
  expect_contains(message_of<InputError>([&] { parse_decomposition(text, "long.toml"); }),
                  {"long.toml:", "subdomain[1].name", "3000 characters long, over the limit of 100"});
}

}  // namespace
}  // namespace bemcontact::io
