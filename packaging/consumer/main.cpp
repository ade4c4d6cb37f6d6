// Solves a small problem through the installed library and prints the library's version
// and the tip displacement: the packaging test checks both.
#include <cstdio>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/io/problem_file.hpp"

int main() {
  const char* text = R"(analysis = "plane_stress"
[material]
E = 1000.0
nu = 0.25
[vertices]
A = [0.0, 0.0]
B = [1.0, 0.0]
C = [1.0, 1.0]
D = [0.0, 1.0]
[[boundary]]
name = "bottom"
from = "A"
to = "B"
elements = 4
u2 = 0.0
[[boundary]]
name = "right"
from = "B"
to = "C"
elements = 4
[[boundary]]
name = "top"
from = "C"
to = "D"
elements = 4
t2 = 10.0
[[boundary]]
name = "left"
from = "D"
to = "A"
elements = 4
u1 = 0.0
)";
  const auto file = bemcontact::io::parse_problem(text, "square.toml");
  const auto result = bemcontact::bem::solve_body(file.problem);
  double top = 0.0;
  for (std::size_t i = 0; i < result.boundary.displacement.size(); ++i) top = std::max(top, result.boundary.displacement[i].y());
  std::printf("bemcontact %s\nu2_top %.12g\n", BEMCONTACT_VERSION, top);
  return 0;
}
