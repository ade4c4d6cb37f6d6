// Solves a problem file through the installed library (the packaging test passes the
// installed examples/plate_tension.toml) and prints the library's version and the largest
// u2 on the boundary.
#include <algorithm>
#include <cstdio>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/io/input/problem_file.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer PROBLEM_FILE\n");
    return 2;
  }
  const auto file = bemcontact::io::read_problem_file(argv[1]);
  const auto result = bemcontact::bem::solve_body(file.problem);
  double top = 0.0;
  for (const auto& u : result.boundary.displacement) top = std::max(top, u.y());
  std::printf("bemcontact %s\nu2_max %.12g\n", BEMCONTACT_VERSION, top);
  return 0;
}
