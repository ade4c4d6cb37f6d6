#pragma once
#include <string>

namespace bemcontact::test_support {

// The plastic tube (examples/plastic_tube.toml: to 1.5 p_y and unloaded) as two regions
// bonded along r = 1.5: an elastoplastic inner ring with cells of `size` and an elastic
// outer ring (the plastic radius is 1.33). It runs through the contact model without a
// contact (the bond eliminated again with the cells' response at every Newton iteration).
// `interior`: a [body.region.interior] table for both regions.
inline std::string bonded_tube(double size, const std::string& interior = "") {
  const std::string roller_x = "u2 = 0.0\nt1 = 0.0\n", roller_y = "u1 = 0.0\nt2 = 0.0\n";
  const auto side = [](const std::string& name, const std::string& from, const std::string& to, int elements,
                       const std::string& more) {
    return "[[body.region.boundary]]\nname = \"" + name + "\"\nfrom = \"" + from + "\"\nto = \"" + to +
           "\"\nelements = " + std::to_string(elements) + "\n" + more;
  };
  const std::string arc = "shape = \"arc\"\ncenter = [0.0, 0.0]\n";
  return "title = \"bonded tube\"\nanalysis = \"plane_strain\"\n[parameters]\na = 1.0\nb = 2.0\nc = 1.5\nY = 250.0\n"
         "py = \"Y / sqrt(0.5 * ((8/3)^2 + (5/3 - 0.2)^2 + 1.2^2))\"\n[[body]]\nname = \"tube\"\n"
         "[[body.region]]\nname = \"inner ring\"\n[body.region.material]\nE = 200000.0\nnu = 0.3\n"
         "yield_stress = \"Y\"\n[body.region.cells]\nsize = " + std::to_string(size) + "\n" + interior +
         "[body.region.vertices]\nA = [\"a\", 0.0]\nP = [\"c\", 0.0]\nQ = [0.0, \"c\"]\nD = [0.0, \"a\"]\n" +
         side("inner x", "A", "P", 10, roller_x) + side("bond", "P", "Q", 24, arc + "interface = \"ring\"\n") +
         side("inner y", "Q", "D", 10, roller_y) +
         side("inner", "D", "A", 32, arc + "direction = \"cw\"\npressure = \"py\"\n") +
         "[[body.region]]\nname = \"outer ring\"\n[body.region.material]\nE = 200000.0\nnu = 0.3\n"
         "[body.region.vertices]\nP = [\"c\", 0.0]\nB = [\"b\", 0.0]\nC = [0.0, \"b\"]\nQ = [0.0, \"c\"]\n" + interior +
         side("outer x", "P", "B", 10, roller_x) + side("outer", "B", "C", 32, arc) +
         side("outer y", "C", "Q", 10, roller_y) +
         side("bond outside", "Q", "P", 24, arc + "direction = \"cw\"\ninterface = \"ring\"\n") +
         "[history]\ndata_amplitude = [[0.0, 0.0], [1.0, 1.5], [2.0, 0.0]]\nend_time = 2.0\n"
         "[solver]\nincrements = 20\n";
}

}  // namespace bemcontact::test_support
