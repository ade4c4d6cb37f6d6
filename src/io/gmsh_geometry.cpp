#include "bemcontact/io/gmsh_geometry.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/toml_reader.hpp"

#ifdef BEMCONTACT_WITH_GMSH
#include <dlfcn.h>
#include <gmshc.h>

#include <fstream>
#include <mutex>
#include <type_traits>
#endif

namespace bemcontact::io {

namespace {

using geometry::BoundaryPiece;
using geometry::PieceShape;

// The lines of a .msh text with their numbers, read section by section.
class MshLines {
 public:
  MshLines(std::string_view text, std::string file) : file_(std::move(file)) {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      std::string line(text.substr(start, end - start));
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines_.push_back(std::move(line));
      start = end + 1;
    }
  }
  bool done() const { return next_ >= lines_.size(); }
  int line_number() const { return static_cast<int>(next_); }  // of the line last read
  const std::string& read() {
    if (done()) fail("the file ends inside a section");
    return lines_[next_++];
  }
  std::istringstream read_words() { return std::istringstream(read()); }
  // Reads `count` lines, handing each to `read_line` as words.
  template <class ReadLine>
  void each_line(long count, const ReadLine& read_line) {
    for (long k = 0; k < count; ++k) {
      auto words = read_words();
      read_line(words);
    }
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{file_, line_number(), section_}, message);
  }
  void enter(const std::string& section) { section_ = section; }
  // Skips to $End<section>.
  void skip_section() {
    const std::string end = "$End" + section_.substr(1);
    while (read() != end) {
    }
  }

 private:
  std::string file_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
  std::string section_;
};

template <class... Values>
void read_values(MshLines& lines, std::istringstream& words, Values&... values) {
  if (!((words >> values) && ...)) lines.fail("cannot read the numbers of this line");
}

std::string quoted_name(const std::string& line) {
  const auto first = line.find('"');
  const auto last = line.rfind('"');
  return first == std::string::npos || last <= first ? "" : line.substr(first + 1, last - first - 1);
}

struct RawMesh {
  std::map<int, std::string> physical_names;            // dim-1 tag -> name
  std::map<int, std::vector<int>> curve_physicals;      // (4.1) curve entity -> physical tags
  std::map<int, std::vector<std::array<long, 2>>> by_physical;  // physical tag -> elements
  std::vector<int> physical_order;                      // first appearance
  std::vector<std::pair<long, Vec2>> nodes;
};

void add_element(RawMesh& mesh, int physical, long a, long b) {
  if (!mesh.by_physical.count(physical)) mesh.physical_order.push_back(physical);
  mesh.by_physical[physical].push_back({a, b});
}

// Line elements: type 1 (2 nodes) and 8 (3 nodes: ends first); other types are not boundary.
int line_nodes(int type) { return type == 1 ? 2 : type == 8 ? 3 : 0; }
int element_node_count(int type) {
  static const std::map<int, int> counts{{1, 2}, {2, 3}, {3, 4}, {4, 4}, {5, 8}, {6, 6}, {7, 5}, {8, 3},
                                         {9, 6}, {10, 9}, {11, 10}, {15, 1}, {16, 8}, {21, 10}, {26, 4}, {27, 5}};
  const auto found = counts.find(type);
  return found == counts.end() ? -1 : found->second;
}

}  // namespace

namespace {

// A format-4 section: "blocks count min_tag max_tag", then per block a line
// "dim entity third count" (third: parametric flag or element type) and its lines,
// which `read_block(dim, entity, third, count)` reads.
template <class ReadBlock>
void each_block(MshLines& lines, std::istringstream& words, const ReadBlock& read_block) {
  long blocks = 0, count = 0, min_tag = 0, max_tag = 0;
  read_values(lines, words, blocks, count, min_tag, max_tag);
  for (long b = 0; b < blocks; ++b) {
    auto block = lines.read_words();
    int dim = 0, entity = 0, third = 0;
    long in_block = 0;
    read_values(lines, block, dim, entity, third, in_block);
    read_block(dim, entity, third, in_block);
  }
}

// $Entities (format 4): the physical groups of each curve.
void read_entities(MshLines& lines, RawMesh& mesh) {
  auto words = lines.read_words();
  long points = 0, curves = 0, surfaces = 0, volumes = 0;
  read_values(lines, words, points, curves, surfaces, volumes);
  lines.each_line(points, [](std::istringstream&) {});
  lines.each_line(curves, [&](std::istringstream& entry) {
    int tag = 0, physicals = 0;
    double box[6];
    read_values(lines, entry, tag, box[0], box[1], box[2], box[3], box[4], box[5], physicals);
    for (int p = 0; p < physicals; ++p) {
      int physical = 0;
      read_values(lines, entry, physical);
      mesh.curve_physicals[tag].push_back(std::abs(physical));
    }
  });
}

void read_nodes(MshLines& lines, double version, RawMesh& mesh) {
  auto words = lines.read_words();
  if (version < 4.0) {  // count, then "tag x y z" per line
    long count = 0;
    read_values(lines, words, count);
    lines.each_line(count, [&](std::istringstream& entry) {
      long tag = 0;
      double x = 0, y = 0, z = 0;
      read_values(lines, entry, tag, x, y, z);
      mesh.nodes.emplace_back(tag, Vec2(x, y));
    });
    return;
  }
  // Format 4: blocks of tags, then their coordinates.
  each_block(lines, words, [&](int, int, int, long in_block) {
    std::vector<long> tags;
    lines.each_line(in_block, [&](std::istringstream& entry) {
      read_values(lines, entry, tags.emplace_back());
    });
    for (const long tag : tags) {
      auto entry = lines.read_words();
      double x = 0, y = 0, z = 0;
      read_values(lines, entry, x, y, z);
      mesh.nodes.emplace_back(tag, Vec2(x, y));
    }
  });
}

// The end nodes of a line element (`count` nodes, ends first) from the rest of its line.
std::array<long, 2> line_ends(MshLines& lines, std::istringstream& entry, int count) {
  std::array<long, 3> nodes{};
  for (int a = 0; a < count; ++a) read_values(lines, entry, nodes[a]);
  return {nodes[0], nodes[1]};
}

void read_elements(MshLines& lines, double version, RawMesh& mesh) {
  auto words = lines.read_words();
  if (version < 4.0) {  // "tag type ntags tags... nodes..." per line, physical tag first
    long count = 0;
    read_values(lines, words, count);
    lines.each_line(count, [&](std::istringstream& entry) {
      long tag = 0;
      int type = 0, tags = 0;
      read_values(lines, entry, tag, type, tags);
      std::vector<long> values(tags);
      for (auto& v : values) read_values(lines, entry, v);
      const int n = line_nodes(type);
      if (n == 0) return;
      const auto ends = line_ends(lines, entry, n);
      if (tags < 1) lines.fail("a line element without a physical tag: give every boundary curve a physical name");
      add_element(mesh, static_cast<int>(values[0]), ends[0], ends[1]);
    });
    return;
  }
  // Format 4: blocks per entity; a curve's physical groups come from $Entities.
  each_block(lines, words, [&](int dim, int entity, int type, long in_block) {
    const int n = dim == 1 ? line_nodes(type) : 0;
    if (element_node_count(type) < 0) lines.fail("unknown element type " + std::to_string(type));
    lines.each_line(in_block, [&](std::istringstream& entry) {
      if (n == 0) return;
      long tag = 0;
      read_values(lines, entry, tag);
      const auto ends = line_ends(lines, entry, n);
      const auto physicals = mesh.curve_physicals.find(entity);
      if (physicals == mesh.curve_physicals.end() || physicals->second.empty())
        lines.fail("curve " + std::to_string(entity) +
                   " has no physical group: give every boundary curve a physical name");
      for (const int physical : physicals->second) add_element(mesh, physical, ends[0], ends[1]);
    });
  });
}

}  // namespace

GmshCurves parse_msh(std::string_view text, const std::string& file) {
  MshLines lines(text, file);
  RawMesh mesh;
  double version = 0.0;
  while (!lines.done()) {
    const std::string header = lines.read();
    if (header.empty() || header[0] != '$') continue;
    lines.enter(header);
    if (header == "$MeshFormat") {
      auto words = lines.read_words();
      int binary = 0, size = 0;
      read_values(lines, words, version, binary, size);
      if (binary != 0)
        lines.fail("a binary .msh file; save it as ASCII (Gmsh: File > Export with 'Save all' off and "
                   "format ASCII, or gmsh -1 FILE.geo -format msh41 -save)");
      if (!(version == 2.2 || (version >= 4.0 && version < 5.0)))
        lines.fail("mesh format " + std::to_string(version) + " is not read; use 2.2 or 4.1");
    } else if (header == "$PhysicalNames") {
      auto words = lines.read_words();
      long count = 0;
      read_values(lines, words, count);
      for (long k = 0; k < count; ++k) {
        const std::string& line = lines.read();
        std::istringstream entry(line);
        int dim = 0, tag = 0;
        read_values(lines, entry, dim, tag);
        if (dim == 1) mesh.physical_names[tag] = quoted_name(line);
      }
    } else if (header == "$Entities" && version >= 4.0) {
      read_entities(lines, mesh);
    } else if (header == "$Nodes") {
      read_nodes(lines, version, mesh);
    } else if (header == "$Elements") {
      read_elements(lines, version, mesh);
    }
    lines.skip_section();
  }
  if (version == 0.0) lines.fail("not a Gmsh .msh file: no $MeshFormat section");
  GmshCurves out;
  out.nodes = std::move(mesh.nodes);
  for (const int physical : mesh.physical_order) {
    const auto name = mesh.physical_names.find(physical);
    out.curves.push_back(GmshCurve{name != mesh.physical_names.end() && !name->second.empty()
                                       ? name->second
                                       : std::to_string(physical),
                                   std::move(mesh.by_physical[physical])});
  }
  if (out.curves.empty())
    throw InputError(SourceLocation{file, 0, "$Elements"},
                     "no line elements in physical curves: define Physical Curve(\"name\") = {...} for the "
                     "boundary and mesh in 1D (gmsh -1)");
  return out;
}

namespace {

// A physical curve's nodes in order along it.
std::vector<long> chain_curve(const GmshCurve& curve, const std::string& file) {
  std::map<long, std::vector<std::size_t>> at;
  for (std::size_t e = 0; e < curve.elements.size(); ++e)
    for (const long node : curve.elements[e]) at[node].push_back(e);
  // Gmsh writes a curve's elements in its direction: start where its first element does.
  long start = curve.elements.front()[0];
  int ends = 0;
  for (const auto& [node, elements] : at) {
    if (elements.size() > 2)
      throw InputError(SourceLocation{file, 0, curve.name},
                       "physical curve '" + curve.name + "' branches at node " + std::to_string(node) +
                           ": a boundary is one line or one arc");
    if (elements.size() == 1) ++ends;
  }
  if (at[start].size() != 1)
    for (const auto& [node, elements] : at)
      if (elements.size() == 1) start = node;
  if (ends == 0)
    throw InputError(SourceLocation{file, 0, curve.name},
                     "physical curve '" + curve.name + "' is closed: split it into two or more curves with their own "
                     "physical names (bemcontact's boundaries are lines and arcs between two points)");
  std::vector<bool> used(curve.elements.size(), false);
  std::vector<long> path{start};
  for (;;) {
    bool advanced = false;
    for (const std::size_t e : at[path.back()]) {
      if (used[e]) continue;
      used[e] = true;
      const auto& el = curve.elements[e];
      path.push_back(el[0] == path.back() ? el[1] : el[0]);
      advanced = true;
      break;
    }
    if (!advanced) break;
  }
  if (path.size() != curve.elements.size() + 1)
    throw InputError(SourceLocation{file, 0, curve.name},
                     "physical curve '" + curve.name + "' has separate parts: give each part its own physical name");
  return path;
}

// A line or an arc through the points, with the element count and grading of the path.
BoundaryPiece piece_from_points(const std::string& name, const std::vector<Vec2>& points, const std::string& file) {
  BoundaryPiece piece;
  piece.name = name;
  piece.where = SourceLocation{file, 0, name};
  piece.start = points.front();
  piece.end = points.back();
  piece.elements = static_cast<int>(points.size()) - 1;
  const Vec2 chord = piece.end - piece.start;
  const double length = chord.norm();
  double path_length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) path_length += (points[k] - points[k - 1]).norm();
  double off_line = 0.0;
  for (const auto& p : points)
    off_line = std::max(off_line, std::abs(chord.x() * (p - piece.start).y() - chord.y() * (p - piece.start).x()) /
                                      std::max(length, 1e-300));
  // Gmsh writes coordinates with 16 digits: 1e-9 of the length is far above round-off.
  if (off_line > 1e-9 * path_length) {
    // The circle through the first, middle and last points (their perpendicular bisectors).
    const Vec2 a = points.front(), b = points[points.size() / 2], c = points.back();
    const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
    const double a2 = a.squaredNorm(), b2 = b.squaredNorm(), c2 = c.squaredNorm();
    const Vec2 center((a2 * (b.y() - c.y()) + b2 * (c.y() - a.y()) + c2 * (a.y() - b.y())) / d,
                      (a2 * (c.x() - b.x()) + b2 * (a.x() - c.x()) + c2 * (b.x() - a.x())) / d);
    const double radius = (a - center).norm();
    double deviation = 0.0;
    for (const auto& p : points) deviation = std::max(deviation, std::abs((p - center).norm() - radius));
    if (!std::isfinite(radius) || deviation > 1e-6 * radius)
      throw InputError(SourceLocation{file, 0, name},
                       "physical curve '" + name + "' is neither a straight line nor a circular arc (its nodes leave "
                           "the circle through its ends and middle by " + std::to_string(deviation) +
                           "): bemcontact's boundaries are lines and arcs, so split it into such curves with their "
                           "own physical names");
    piece.shape = PieceShape::arc;
    piece.center = center;
    const Vec2 u = a - center, v = points[1] - center;
    piece.counterclockwise = u.x() * v.y() - u.y() * v.x() > 0.0;
  }
  // Grading: the ratio of the longest to the shortest element, short ones at their end.
  const double first = (points[1] - points[0]).norm();
  const double last = (points.back() - points[points.size() - 2]).norm();
  double longest = 0.0, shortest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double h = (points[k] - points[k - 1]).norm();
    longest = std::max(longest, h), shortest = std::min(shortest, h);
  }
  if (piece.elements > 1 && longest > 1.01 * shortest) {
    piece.grading = longest / shortest;
    piece.refine_toward = first <= last ? geometry::RefineToward::start : geometry::RefineToward::end;
  }
  return piece;
}

void reverse(BoundaryPiece& piece) {
  std::swap(piece.start, piece.end);
  piece.counterclockwise = !piece.counterclockwise;
  piece.refine_toward = piece.refine_toward == geometry::RefineToward::start ? geometry::RefineToward::end
                                                                             : geometry::RefineToward::start;
}

// Points along a piece (arcs sampled) for areas and inclusion tests.
std::vector<Vec2> outline(const BoundaryPiece& piece) {
  if (piece.shape == PieceShape::line) return {piece.start};
  std::vector<Vec2> out;
  const Vec2 u = piece.start - piece.center, v = piece.end - piece.center;
  const double a0 = std::atan2(u.y(), u.x());
  double sweep = std::atan2(v.y(), v.x()) - a0;
  if (piece.counterclockwise && sweep <= 0.0) sweep += 2.0 * M_PI;
  if (!piece.counterclockwise && sweep >= 0.0) sweep -= 2.0 * M_PI;
  const double r = u.norm();
  for (int k = 0; k < 32; ++k) {
    const double t = a0 + sweep * k / 32.0;
    out.emplace_back(piece.center.x() + r * std::cos(t), piece.center.y() + r * std::sin(t));
  }
  return out;
}

double signed_area(const std::vector<Vec2>& polygon) {
  double area = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec2& p = polygon[k];
    const Vec2& q = polygon[(k + 1) % polygon.size()];
    area += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * area;
}

bool inside(const std::vector<Vec2>& polygon, const Vec2& point) {
  bool in = false;
  for (std::size_t k = 0, j = polygon.size() - 1; k < polygon.size(); j = k++) {
    const Vec2& a = polygon[k];
    const Vec2& b = polygon[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

}  // namespace

GmshBoundary boundary_from_curves(const GmshCurves& curves, bool axisymmetric, const std::string& file) {
  std::map<long, Vec2> node_at(curves.nodes.begin(), curves.nodes.end());
  GmshBoundary out;
  std::set<std::string> names;
  double size = 0.0;
  for (const auto& curve : curves.curves) {
    if (!names.insert(curve.name).second)
      throw InputError(SourceLocation{file, 0, curve.name}, "two physical curves are named '" + curve.name + "'");
    std::vector<Vec2> points;
    for (const long node : chain_curve(curve, file)) {
      const auto found = node_at.find(node);
      if (found == node_at.end())
        throw InputError(SourceLocation{file, 0, curve.name},
                         "physical curve '" + curve.name + "' uses node " + std::to_string(node) + ", which is not in $Nodes");
      points.push_back(found->second);
    }
    out.pieces.push_back(piece_from_points(curve.name, points, file));
    for (const auto& p : points) size = std::max(size, p.norm());
  }
  // Chain the pieces into loops by their end points; orient each loop.
  const double tolerance = 1e-9 * std::max(size, 1e-300);
  const auto same = [tolerance](const Vec2& a, const Vec2& b) { return (a - b).norm() <= tolerance; };
  const std::size_t n = out.pieces.size();
  std::vector<bool> used(n, false);
  struct Loop {
    std::vector<std::pair<std::size_t, bool>> pieces;  // piece, travelled forward
    std::vector<Vec2> polygon;
  };
  std::vector<Loop> loops;
  for (std::size_t first = 0; first < n; ++first) {
    if (used[first]) continue;
    Loop loop;
    // Walk forward from the first piece's end, then backward from its start if it does not close.
    std::deque<std::pair<std::size_t, bool>> chain{{first, true}};
    used[first] = true;
    const auto end_of = [&](const std::pair<std::size_t, bool>& p) {
      return p.second ? out.pieces[p.first].end : out.pieces[p.first].start;
    };
    const auto start_of = [&](const std::pair<std::size_t, bool>& p) {
      return p.second ? out.pieces[p.first].start : out.pieces[p.first].end;
    };
    const auto extend = [&](bool at_end) {
      for (;;) {
        const Vec2 tip = at_end ? end_of(chain.back()) : start_of(chain.front());
        if (same(tip, at_end ? start_of(chain.front()) : end_of(chain.back()))) return true;
        bool found = false;
        for (std::size_t k = 0; k < n && !found; ++k) {
          if (used[k]) continue;
          for (const bool forward : {true, false}) {
            const std::pair<std::size_t, bool> candidate{k, forward};
            if (same(at_end ? start_of(candidate) : end_of(candidate), tip)) {
              used[k] = true;
              if (at_end) chain.push_back(candidate);
              else chain.push_front(candidate);
              found = true;
              break;
            }
          }
        }
        if (!found) return false;
      }
    };
    bool closed = extend(true);
    if (!closed) closed = extend(false);
    if (!closed) {
      const Vec2 a = start_of(chain.front()), b = end_of(chain.back());
      const bool on_axis = axisymmetric && std::abs(a.x()) <= tolerance && std::abs(b.x()) <= tolerance;
      if (!on_axis) {
        std::ostringstream where;
        where << "(" << b.x() << ", " << b.y() << ")";
        throw InputError(SourceLocation{file, 0, out.pieces[chain.back().first].name},
                         "the physical curves do not close: curve '" + out.pieces[chain.back().first].name +
                             "' ends at " + where.str() +
                             " where no other physical curve starts (every boundary curve needs a physical name" +
                             std::string(axisymmetric ? "; in axisymmetry an open chain must end on the axis r = 0)"
                                                      : ")"));
      }
    }
    loop.pieces.assign(chain.begin(), chain.end());
    for (const auto& [piece, forward] : loop.pieces) {
      BoundaryPiece travelled = out.pieces[piece];
      if (!forward) reverse(travelled);
      for (const auto& p : outline(travelled)) loop.polygon.push_back(p);
    }
    loops.push_back(std::move(loop));
  }
  // Outer loops (inside no other) counter-clockwise, holes clockwise.
  std::vector<bool> flipped(n, false);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    int depth = 0;
    for (std::size_t m = 0; m < loops.size(); ++m)
      if (m != l && inside(loops[m].polygon, loops[l].polygon.front())) ++depth;
    const bool want_ccw = depth % 2 == 0;
    const bool is_ccw = signed_area(loops[l].polygon) > 0.0;
    for (const auto& [piece, forward] : loops[l].pieces) flipped[piece] = (forward != (want_ccw == is_ccw));
  }
  for (std::size_t k = 0; k < n; ++k)
    if (flipped[k]) {
      reverse(out.pieces[k]);
      out.reversed.push_back(out.pieces[k].name);
    }
  return out;
}

#ifdef BEMCONTACT_WITH_GMSH
namespace {

// The Gmsh library, opened on first use only (a .geo file): the command starts without
// loading it and its dependencies. The function types come from the C API header of the
// version built against, whose library file (BEMCONTACT_GMSH_LIBRARY) is the one opened.
struct GmshApi {
  decltype(&gmshInitialize) initialize = nullptr;
  decltype(&gmshFinalize) finalize = nullptr;
  decltype(&gmshOpen) open = nullptr;
  decltype(&gmshWrite) write = nullptr;
  decltype(&gmshOptionSetNumber) set_number = nullptr;
  decltype(&gmshModelMeshGenerate) generate = nullptr;
  decltype(&gmshLoggerGetLastError) last_error = nullptr;
  decltype(&gmshFree) free = nullptr;
  std::string failure;  // why it could not be opened
};

const GmshApi& gmsh_library() {
  static const GmshApi api = [] {
    GmshApi out;
    void* handle = ::dlopen(BEMCONTACT_GMSH_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* error = ::dlerror();
      out.failure = error ? error : "cannot open " BEMCONTACT_GMSH_LIBRARY;
      return out;
    }
    const auto find = [&](auto& function, const char* name) {
      function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(::dlsym(handle, name));
      if (!function && out.failure.empty()) out.failure = std::string("no ") + name + " in " BEMCONTACT_GMSH_LIBRARY;
    };
    find(out.initialize, "gmshInitialize");
    find(out.finalize, "gmshFinalize");
    find(out.open, "gmshOpen");
    find(out.write, "gmshWrite");
    find(out.set_number, "gmshOptionSetNumber");
    find(out.generate, "gmshModelMeshGenerate");
    find(out.last_error, "gmshLoggerGetLastError");
    find(out.free, "gmshFree");
    return out;
  }();
  return api;
}

// Gmsh's last error message, or `fallback`.
std::string gmsh_error(const GmshApi& api, const std::string& fallback) {
  char* text = nullptr;
  int ierr = 0;
  api.last_error(&text, &ierr);
  std::string out = text && *text ? text : fallback;
  if (text) api.free(text);
  return out;
}

}  // namespace
#endif

bool gmsh_api_available() {
#ifdef BEMCONTACT_WITH_GMSH
  return gmsh_library().failure.empty();
#else
  return false;
#endif
}

GmshCurves mesh_geo(const std::filesystem::path& file) {
#ifdef BEMCONTACT_WITH_GMSH
  const GmshApi& api = gmsh_library();
  if (!api.failure.empty())
    throw InputError(SourceLocation{file.string(), 0, ""},
                     "reading a .geo file needs the Gmsh library (" + api.failure + "; apt-get install libgmsh4.8), "
                     "or mesh it with gmsh -1 " + file.filename().string() + " -format msh41 and give the .msh file");
  // The Gmsh API holds one global model: one file at a time.
  static std::mutex gmsh_mutex;
  const std::lock_guard<std::mutex> lock(gmsh_mutex);
  const auto temporary = std::filesystem::temp_directory_path() /
                         ("bemcontact-" + std::to_string(::getpid()) + "-" + file.stem().string() + ".msh");
  std::string error;
  int ierr = 0;
  char program[] = "bemcontact";
  char* argv[] = {program, nullptr};
  api.initialize(1, argv, 0, &ierr);
  if (ierr) error = gmsh_error(api, "Gmsh did not start");
  const auto step = [&](auto call, const char* what) {
    if (!error.empty()) return;
    call();
    if (ierr) error = gmsh_error(api, what);
  };
  step([&] { api.set_number("General.Terminal", 0, &ierr); }, "cannot set General.Terminal");
  step([&] { api.set_number("Mesh.MshFileVersion", 4.1, &ierr); }, "cannot set Mesh.MshFileVersion");
  step([&] { api.set_number("Mesh.Binary", 0, &ierr); }, "cannot set Mesh.Binary");
  step([&] { api.open(file.c_str(), &ierr); }, "cannot open the file");
  step([&] { api.generate(1, &ierr); }, "cannot mesh the curves");
  step([&] { api.write(temporary.c_str(), &ierr); }, "cannot write the mesh");
  std::string text;
  if (error.empty()) {
    std::ifstream in(temporary);
    std::ostringstream content;
    content << in.rdbuf();
    text = content.str();
  }
  api.finalize(&ierr);
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  if (!error.empty()) throw InputError(SourceLocation{file.string(), 0, ""}, "Gmsh could not mesh the file: " + error);
  return parse_msh(text, file.string());
#else
  throw InputError(SourceLocation{file.string(), 0, ""},
                   "this build of bemcontact reads .geo files only with the Gmsh library (libgmsh-dev, CMake "
                   "option BEMCONTACT_WITH_GMSH); mesh it with gmsh -1 " + file.filename().string() +
                       " -format msh41 and give the .msh file");
#endif
}

GmshBoundary read_gmsh_boundary(const std::filesystem::path& file, bool axisymmetric) {
  const std::string extension = file.extension().string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    throw InputError(SourceLocation{file.string(), 0, ""},
                     std::filesystem::exists(file, error) ? "the Gmsh file is not a regular file"
                                                          : "cannot read the Gmsh file: no such file");
  if (extension == ".geo") return boundary_from_curves(mesh_geo(file), axisymmetric, file.string());
  if (extension == ".msh")
    return boundary_from_curves(parse_msh(read_problem_text(file), file.string()), axisymmetric, file.string());
  throw InputError(SourceLocation{file.string(), 0, ""}, "a Gmsh geometry is a .geo or .msh file, found '" +
                                                             file.filename().string() + "'");
}

}  // namespace bemcontact::io
