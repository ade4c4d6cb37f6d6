#pragma once
// Boundaries drawn in Gmsh: the physical curves of a .msh file (ASCII, format 2.2 or 4.1),
// or of a .geo file meshed in 1D through the Gmsh API (when built with libgmsh), become
// the body's boundary pieces, named by their physical names. Conditions, materials and
// contacts still come from the problem file, by those names (docs/gmsh.md).
//
// Each physical curve must be one straight line or one circular arc (the piece shapes of
// bemcontact); its element count and end-to-end grading are taken from the Gmsh mesh.
// The curves are oriented so that the body lies on their left (outer contours
// counter-clockwise, holes clockwise): a curve drawn the other way is reversed.
#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/core/types.hpp"
#include "bemcontact/geometry/boundary.hpp"

namespace bemcontact::io {

// The line elements of the physical curves of a mesh, by physical name (its tag as text
// when the group has no name), in the order of the file.
struct GmshCurve {
  std::string name;
  std::vector<std::array<long, 2>> elements;  // end node tags of each line element
};
struct GmshCurves {
  std::vector<GmshCurve> curves;
  std::vector<std::pair<long, Vec2>> nodes;  // tag, (x, y)
};

// Reads the text of a .msh file; `file` names it in messages (InputError with the line):
// counts that are negative or do not match the lines of their section, and more than
// `max_elements` line elements on the physical curves, are refused.
GmshCurves parse_msh(std::string_view text, const std::string& file,
                     std::int64_t max_elements = std::numeric_limits<std::int64_t>::max());

// How a Gmsh file is read: the run's limits (elements of one body, memory, the time a
// .geo may take to mesh) and the numbers given to a .geo as `gmsh -setnumber NAME VALUE`
// does (they replace the defaults of its DefineConstant[NAME = ...]).
struct GmshOptions {
  ResourceLimits limits;
  std::map<std::string, double> numbers;
};

// Meshes a .geo file in 1D with the Gmsh API, in a child process bounded in time
// (limits.gmsh_timeout_seconds) and memory (gmsh_meshing_bytes); InputError when this
// build has no Gmsh, Gmsh reports an error, or a limit stops it.
GmshCurves mesh_geo(const std::filesystem::path& file, const GmshOptions& options = {});
bool gmsh_api_available();
// The memory Gmsh may take to mesh a boundary within the limits: 64 MB and 1 kB per
// element allowed (Gmsh takes about 160 B per 1D element), at most the memory limit.
double gmsh_meshing_bytes(const ResourceLimits& limits);

// The names a .geo text declares with DefineConstant[NAME = ..., ...] (comments and
// strings skipped): those a -setnumber value replaces.
std::set<std::string> geo_constants(std::string_view text);

struct GmshBoundary {
  std::vector<geometry::BoundaryPiece> pieces;  // one per physical curve, in file order
  std::vector<std::string> reversed;            // the curves turned to have the body on their left
};

// Lines and arcs from the curves, checked and oriented. In axisymmetry a chain whose two
// ends are on the axis r = 0 is closed by the axis. Throws InputError naming the file and
// the curve.
GmshBoundary boundary_from_curves(const GmshCurves& curves, bool axisymmetric, const std::string& file);

// .msh or .geo by extension; a .msh file is refused when reading it would take more than
// the memory limit.
GmshBoundary read_gmsh_boundary(const std::filesystem::path& file, bool axisymmetric,
                                const GmshOptions& options = {});

}  // namespace bemcontact::io
