#include "bemcontact/io/input/gmsh_geometry.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "bemcontact/core/error.hpp"
#include "io/input/toml_reader.hpp"
#include "bemcontact/io/input/problem_text.hpp"

#ifdef BEMCONTACT_WITH_GMSH
#include <dlfcn.h>
#include <gmshc.h>
#include <stdlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <type_traits>

#include "bemcontact/io/input/child_process.hpp"
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
    section_end_ = lines_.size();
  }
  bool done() const { return next_ >= lines_.size(); }
  int line_number() const { return static_cast<int>(next_); }  // of the line last read
  const std::string& read() {
    if (next_ >= section_end_)
      fail(section_.empty() ? "the file ends inside a section"
                            : "the section ends (" + end_name() + " at line " + std::to_string(section_end_ + 1) +
                                  ") before the entries its counts announce: the counts do not match the content");
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
  [[noreturn]] void fail(const std::string& message) const { fail_at(line_number(), message); }
  [[noreturn]] void fail_at(int line, const std::string& message) const {
    throw InputError(SourceLocation{file_, line, section_}, message);
  }
  // A section starts: its $End line is found first, so that counts can be checked against it.
  void enter(const std::string& section) {
    section_ = section;
    section_end_ = next_;
    while (section_end_ < lines_.size() && lines_[section_end_] != end_name()) ++section_end_;
    if (section_end_ == lines_.size()) fail("no " + end_name() + ": the file ends inside the section");
  }
  // The count `what` of the line `words`: >= 0, its entries (`lines_each` lines each)
  // within the section.
  long read_count(std::istringstream& words, const std::string& what, long lines_each = 1) {
    long count = 0;
    if (!(words >> count)) fail("cannot read the number of " + what);
    check_count(count, what, lines_each);
    return count;
  }
  void check_count(long count, const std::string& what, long lines_each = 1) const {
    if (count < 0) fail("the number of " + what + " is negative (" + std::to_string(count) + ")");
    const long left = static_cast<long>(section_end_ - next_);
    if (count > left / lines_each)
      fail(std::to_string(count) + " " + what + " announced, but " + end_name() + " comes " + std::to_string(left) +
           " lines further: the counts do not match the content");
  }
  // Every entry read: the next line must be the section's end.
  void expect_end(const std::string& what) {
    if (next_ == section_end_) return;
    ++next_;
    fail("this line follows the " + what + " the section's counts announce, before " + end_name() +
         ": the counts do not match the content");
  }
  // Skips to the line after $End<section>.
  void skip_section() {
    next_ = section_end_ + 1;
    section_end_ = lines_.size();
    section_.clear();
  }

 private:
  std::string end_name() const { return "$End" + section_.substr(std::min<std::size_t>(1, section_.size())); }

  std::string file_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
  std::size_t section_end_ = 0;  // the $End line of the section, or the number of lines
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
  std::int64_t max_elements = 0;    // line elements on the physical curves (--max-elements)
  std::int64_t line_elements = 0;
  std::map<int, std::string> physical_names;            // dim-1 tag -> name
  std::map<int, std::vector<int>> curve_physicals;      // (4.1) curve entity -> physical tags
  std::map<int, std::vector<std::array<long, 2>>> by_physical;  // physical tag -> elements
  std::vector<int> physical_order;                      // first appearance
  std::vector<std::pair<long, Vec2>> nodes;
  std::set<long> node_tags;  // to refuse a tag given twice and an element on a missing node
};

// A node of $Nodes; a tag given twice is refused.
void add_node(MshLines& lines, RawMesh& mesh, long tag, const Vec2& position) {
  if (!mesh.node_tags.insert(tag).second) lines.fail("node " + std::to_string(tag) + " is defined twice");
  mesh.nodes.emplace_back(tag, position);
}

void add_element(MshLines& lines, RawMesh& mesh, int physical, long a, long b) {
  for (const long node : {a, b})
    if (!mesh.node_tags.count(node))
      lines.fail("a line element on node " + std::to_string(node) + ", which $Nodes does not define (or comes after "
                 "$Elements)");
  if (++mesh.line_elements > mesh.max_elements)
    lines.fail("more than " + std::to_string(mesh.max_elements) + " line elements on the physical curves, over the "
               "limit of elements of one body (raise it with --max-elements if the machine has the memory)");
  if (!mesh.by_physical.count(physical)) mesh.physical_order.push_back(physical);
  mesh.by_physical[physical].push_back({a, b});
}

// Line elements: type 1 (2 nodes) and 8 (3 nodes: ends first); other types are not boundary.
int line_nodes(int type) { return type == 1 ? 2 : type == 8 ? 3 : 0; }
// Lines of a higher order (4, 5, 6 nodes): boundary elements that are not read.
void refuse_high_order_line(MshLines& lines, int type) {
  if (type == 26 || type == 27 || type == 28)
    lines.fail("line elements of type " + std::to_string(type) + " (" + std::to_string(type - 22) +
               " nodes) are not read: mesh the curves with elements of order 1 or 2 (types 1 and 8: "
               "Mesh.ElementOrder = 1 or 2)");
}
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
// `lines_each`: lines per entry of a block (nodes: a tag line and a coordinate line).
template <class ReadBlock>
void each_block(MshLines& lines, std::istringstream& words, const std::string& what, long lines_each,
                const ReadBlock& read_block) {
  const int header = lines.line_number();
  const long blocks = lines.read_count(words, "blocks of " + what);
  long count = 0, min_tag = 0, max_tag = 0;
  read_values(lines, words, count, min_tag, max_tag);
  lines.check_count(count, what, lines_each);
  long total = 0;
  for (long b = 0; b < blocks; ++b) {
    auto block = lines.read_words();
    int dim = 0, entity = 0, third = 0;
    long in_block = 0;
    read_values(lines, block, dim, entity, third, in_block);
    lines.check_count(in_block, what + " in this block", lines_each);
    total += in_block;
    read_block(dim, entity, third, in_block);
  }
  if (total != count)
    lines.fail_at(header, std::to_string(count) + " " + what + " announced, but its blocks hold " +
                              std::to_string(total) + ": the counts do not match the content");
  lines.expect_end(what);
}

// $Entities (format 4): the physical groups of each curve.
void read_entities(MshLines& lines, RawMesh& mesh) {
  auto words = lines.read_words();
  const long points = lines.read_count(words, "points"), curves = lines.read_count(words, "curves");
  const long surfaces = lines.read_count(words, "surfaces"), volumes = lines.read_count(words, "volumes");
  lines.check_count(points + curves + surfaces + volumes, "entities");
  lines.each_line(points, [](std::istringstream&) {});
  lines.each_line(curves, [&](std::istringstream& entry) {
    int tag = 0, physicals = 0;
    double box[6];
    read_values(lines, entry, tag, box[0], box[1], box[2], box[3], box[4], box[5], physicals);
    if (physicals < 0) lines.fail("the number of physical groups of curve " + std::to_string(tag) + " is negative");
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
    const long count = lines.read_count(words, "nodes");
    lines.each_line(count, [&](std::istringstream& entry) {
      long tag = 0;
      double x = 0, y = 0, z = 0;
      read_values(lines, entry, tag, x, y, z);
      add_node(lines, mesh, tag, Vec2(x, y));
    });
    lines.expect_end("nodes");
    return;
  }
  // Format 4: blocks of tags, then their coordinates.
  each_block(lines, words, "nodes", 2, [&](int, int, int, long in_block) {
    std::vector<long> tags;
    lines.each_line(in_block, [&](std::istringstream& entry) {
      read_values(lines, entry, tags.emplace_back());
    });
    for (const long tag : tags) {
      auto entry = lines.read_words();
      double x = 0, y = 0, z = 0;
      read_values(lines, entry, x, y, z);
      add_node(lines, mesh, tag, Vec2(x, y));
    }
  });
}

// The end nodes of a line element (`count` nodes, ends first) from the rest of its line,
// which must hold nothing more.
std::array<long, 2> line_ends(MshLines& lines, std::istringstream& entry, int count) {
  std::array<long, 3> nodes{};
  for (int a = 0; a < count; ++a) read_values(lines, entry, nodes[a]);
  std::string extra;
  if (entry >> extra)
    lines.fail("a line element of " + std::to_string(count) + " nodes with more values on its line ('" + extra +
               "'): the element's type and its nodes do not match");
  return {nodes[0], nodes[1]};
}

void read_elements(MshLines& lines, double version, RawMesh& mesh) {
  auto words = lines.read_words();
  if (version < 4.0) {  // "tag type ntags tags... nodes..." per line, physical tag first
    const long count = lines.read_count(words, "elements");
    lines.each_line(count, [&](std::istringstream& entry) {
      long tag = 0, physical = 0;
      int type = 0, tags = 0;
      read_values(lines, entry, tag, type, tags);
      if (tags < 0) lines.fail("the number of tags of element " + std::to_string(tag) + " is negative");
      for (int k = 0; k < tags; ++k) {  // as many as the line holds: a huge count fails here
        long value = 0;
        if (!(entry >> value))
          lines.fail("element " + std::to_string(tag) + " announces " + std::to_string(tags) +
                     " tags, more than its line holds: the counts do not match the content");
        if (k == 0) physical = value;
      }
      refuse_high_order_line(lines, type);
      const int n = line_nodes(type);
      if (n == 0) return;
      const auto ends = line_ends(lines, entry, n);
      if (tags < 1) lines.fail("a line element without a physical tag: give every boundary curve a physical name");
      add_element(lines, mesh, static_cast<int>(physical), ends[0], ends[1]);
    });
    lines.expect_end("elements");
    return;
  }
  // Format 4: blocks per entity; a curve's physical groups come from $Entities.
  each_block(lines, words, "elements", 1, [&](int dim, int entity, int type, long in_block) {
    const int n = dim == 1 ? line_nodes(type) : 0;
    if (element_node_count(type) < 0) lines.fail("unknown element type " + std::to_string(type));
    if (dim == 1) refuse_high_order_line(lines, type);
    lines.each_line(in_block, [&](std::istringstream& entry) {
      if (n == 0) return;
      long tag = 0;
      read_values(lines, entry, tag);
      const auto ends = line_ends(lines, entry, n);
      const auto physicals = mesh.curve_physicals.find(entity);
      if (physicals == mesh.curve_physicals.end() || physicals->second.empty())
        lines.fail("curve " + std::to_string(entity) +
                   " has no physical group: give every boundary curve a physical name");
      for (const int physical : physicals->second) add_element(lines, mesh, physical, ends[0], ends[1]);
    });
  });
}

}  // namespace

GmshCurves parse_msh(std::string_view text, const std::string& file, std::int64_t max_elements) {
  MshLines lines(text, file);
  RawMesh mesh;
  mesh.max_elements = max_elements;
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
      const long count = lines.read_count(words, "physical names");
      for (long k = 0; k < count; ++k) {
        const std::string& line = lines.read();
        std::istringstream entry(line);
        int dim = 0, tag = 0;
        read_values(lines, entry, dim, tag);
        if (dim == 1) mesh.physical_names[tag] = quoted_name(line);
      }
      lines.expect_end("physical names");
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

namespace {

// The physical curves as pieces, in the file's order; the largest distance from the origin.
double pieces_from_curves(const GmshCurves& curves, const std::string& file, GmshBoundary& out) {
  std::map<long, Vec2> node_at(curves.nodes.begin(), curves.nodes.end());
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
  return size;
}

// A closed chain of pieces (piece, travelled forward) and its outline.
struct Loop {
  std::vector<std::pair<std::size_t, bool>> pieces;
  std::vector<Vec2> polygon;
};

// Chains the pieces into loops by their end points: forward from a piece's end, then
// backward from its start if it does not close. An open chain is an error, except one
// ending on the axis in axisymmetry.
std::vector<Loop> chain_loops(const std::vector<BoundaryPiece>& pieces, double size, bool axisymmetric,
                              const std::string& file) {
  const double tolerance = 1e-9 * std::max(size, 1e-300);
  const auto same = [tolerance](const Vec2& a, const Vec2& b) { return (a - b).norm() <= tolerance; };
  const std::size_t n = pieces.size();
  std::vector<bool> used(n, false);
  std::vector<Loop> loops;
  for (std::size_t first = 0; first < n; ++first) {
    if (used[first]) continue;
    Loop loop;
    std::deque<std::pair<std::size_t, bool>> chain{{first, true}};
    used[first] = true;
    const auto end_of = [&](const std::pair<std::size_t, bool>& p) {
      return p.second ? pieces[p.first].end : pieces[p.first].start;
    };
    const auto start_of = [&](const std::pair<std::size_t, bool>& p) {
      return p.second ? pieces[p.first].start : pieces[p.first].end;
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
        throw InputError(SourceLocation{file, 0, pieces[chain.back().first].name},
                         "the physical curves do not close: curve '" + pieces[chain.back().first].name +
                             "' ends at " + where.str() +
                             " where no other physical curve starts (every boundary curve needs a physical name" +
                             std::string(axisymmetric ? "; in axisymmetry an open chain must end on the axis r = 0)"
                                                      : ")"));
      }
    }
    loop.pieces.assign(chain.begin(), chain.end());
    for (const auto& [piece, forward] : loop.pieces) {
      BoundaryPiece travelled = pieces[piece];
      if (!forward) reverse(travelled);
      for (const auto& p : outline(travelled)) loop.polygon.push_back(p);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Outer loops (inside no other) counter-clockwise, holes clockwise: the pieces to reverse.
std::vector<bool> pieces_to_reverse(const std::vector<Loop>& loops, std::size_t pieces) {
  std::vector<bool> flipped(pieces, false);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    int depth = 0;
    for (std::size_t m = 0; m < loops.size(); ++m)
      if (m != l && inside(loops[m].polygon, loops[l].polygon.front())) ++depth;
    const bool want_ccw = depth % 2 == 0;
    const bool is_ccw = signed_area(loops[l].polygon) > 0.0;
    for (const auto& [piece, forward] : loops[l].pieces) flipped[piece] = (forward != (want_ccw == is_ccw));
  }
  return flipped;
}

}  // namespace

GmshBoundary boundary_from_curves(const GmshCurves& curves, bool axisymmetric, const std::string& file) {
  GmshBoundary out;
  const double size = pieces_from_curves(curves, file, out);
  const auto loops = chain_loops(out.pieces, size, axisymmetric, file);
  const auto flipped = pieces_to_reverse(loops, out.pieces.size());
  for (std::size_t k = 0; k < out.pieces.size(); ++k)
    if (flipped[k]) {
      reverse(out.pieces[k]);
      out.reversed.push_back(out.pieces[k].name);
    }
  return out;
}

// The names declared by DefineConstant[...] blocks: identifiers followed by '=' directly
// inside the brackets (not inside the braces of an option list).
std::set<std::string> geo_constants(std::string_view text) {
  std::set<std::string> names;
  const auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::size_t i = 0;
  // Past comments and strings, so that neither hides nor fakes a declaration.
  const auto skip_space = [&] {
    for (;;) {
      while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      if (text.compare(i, 2, "//") == 0) {
        i = std::min(text.find('\n', i), text.size());
      } else if (text.compare(i, 2, "/*") == 0) {
        const auto end = text.find("*/", i + 2);
        i = end == std::string_view::npos ? text.size() : end + 2;
      } else if (i < text.size() && text[i] == '"') {
        for (++i; i < text.size() && text[i] != '"'; ++i)
          if (text[i] == '\\') ++i;
        ++i;
      } else {
        return;
      }
    }
  };
  const auto read_name = [&] {
    const std::size_t start = i;
    while (i < text.size() && name_char(text[i])) ++i;
    return std::string(text.substr(start, i - start));
  };
  while (i < text.size()) {
    skip_space();
    if (i >= text.size()) break;
    if (!name_char(text[i])) {
      ++i;
      continue;
    }
    if (read_name() != "DefineConstant") continue;
    skip_space();
    if (i >= text.size() || text[i] != '[') continue;
    ++i;
    int brackets = 1, braces = 0;
    while (i < text.size() && brackets > 0) {
      skip_space();
      if (i >= text.size()) break;
      const char c = text[i];
      if (name_char(c)) {
        const std::string name = read_name();
        skip_space();
        if (brackets == 1 && braces == 0 && i < text.size() && text[i] == '=' && !std::isdigit(static_cast<unsigned char>(name[0])))
          names.insert(name);
        continue;
      }
      brackets += c == '[' ? 1 : c == ']' ? -1 : 0;
      braces += c == '{' ? 1 : c == '}' ? -1 : 0;
      ++i;
    }
  }
  return names;
}

double gmsh_meshing_bytes(const ResourceLimits& limits) {
  return std::min(limits.memory_limit_bytes(), 64e6 + 1e3 * static_cast<double>(limits.max_elements));
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

// Gmsh's command line: one thread, and the numbers as -setnumber NAME VALUE.
std::vector<std::string> gmsh_arguments(const GmshOptions& options) {
  std::vector<std::string> arguments{"bemcontact", "-nt", "1"};
  for (const auto& [name, value] : options.numbers) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    arguments.insert(arguments.end(), {"-setnumber", name, text});
  }
  return arguments;
}

// In the child process: mesh `file` in 1D and write the mesh to `output` (format 4.1,
// ASCII); on failure Gmsh's message goes to `report_fd`. Returns the exit code.
int mesh_into(const GmshApi& api, const std::filesystem::path& file, const std::filesystem::path& output,
              std::vector<std::string> arguments, int report_fd) {
  std::vector<char*> argv;
  for (auto& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::string error;
  int ierr = 0;
  api.initialize(static_cast<int>(arguments.size()), argv.data(), 0, &ierr);
  if (ierr) error = gmsh_error(api, "Gmsh did not start");
  const auto step = [&](auto call, const char* what) {
    if (!error.empty()) return;
    call();
    if (ierr) error = gmsh_error(api, what);
  };
  step([&] { api.set_number("General.Terminal", 0, &ierr); }, "cannot set General.Terminal");
  step([&] { api.set_number("General.NumThreads", 1, &ierr); }, "cannot set General.NumThreads");
  step([&] { api.set_number("Mesh.MaxNumThreads1D", 1, &ierr); }, "cannot set Mesh.MaxNumThreads1D");
  step([&] { api.set_number("Mesh.MshFileVersion", 4.1, &ierr); }, "cannot set Mesh.MshFileVersion");
  step([&] { api.set_number("Mesh.Binary", 0, &ierr); }, "cannot set Mesh.Binary");
  step([&] { api.open(file.c_str(), &ierr); }, "cannot open the file");
  step([&] { api.generate(1, &ierr); }, "cannot mesh the curves");
  step([&] { api.write(output.c_str(), &ierr); }, "cannot write the mesh");
  if (error.empty()) return 0;
  const ssize_t written = ::write(report_fd, error.data(), error.size());
  (void)written;  // nothing more to do in the child if the report is lost
  return 1;
}

// A file of a unique name for the child's mesh, removed with this object.
struct TemporaryMesh {
  std::filesystem::path path;
  TemporaryMesh() {
    std::string name = (std::filesystem::temp_directory_path() / "bemcontact-gmsh-XXXXXX.msh").string();
    const int fd = ::mkstemps(name.data(), 4);
    if (fd < 0) throw Error("cannot create a temporary file for Gmsh's mesh in " +
                            std::filesystem::temp_directory_path().string() + ": " + std::strerror(errno));
    ::close(fd);
    path = name;
  }
  ~TemporaryMesh() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
  TemporaryMesh(const TemporaryMesh&) = delete;
  TemporaryMesh& operator=(const TemporaryMesh&) = delete;
};

// Why the child did not give a mesh, as the message of an InputError.
std::string meshing_failure(const ChildOutcome& outcome, const GmshOptions& options) {
  const auto& limits = options.limits;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limits.gmsh_timeout_seconds);
  const std::string memory = "Gmsh stopped while meshing the file (" +
                             (outcome.signal ? "by " + signal_text(outcome.signal) : std::string("out of memory")) +
                             "); most likely it went past the " + format_bytes(gmsh_meshing_bytes(limits)) +
                             " that meshing a boundary of at most " + std::to_string(limits.max_elements) +
                             " elements may take (--max-elements, --max-memory); check the element counts "
                             "(Transfinite Curve, point counts, progressions) and the mesh sizes";
  switch (outcome.end) {
    case ChildOutcome::End::timed_out:
      return std::string("Gmsh did not finish meshing the file within ") + seconds +
             " s (--gmsh-timeout): a loop that does not end, or a mesh far finer than the boundary needs "
             "(a tiny mesh size)? Raise --gmsh-timeout if the file is right";
    case ChildOutcome::End::signalled:
      return memory;
    case ChildOutcome::End::failed:
      if (outcome.report.find("bad_alloc") != std::string::npos || outcome.report.empty()) return memory;
      return "Gmsh could not mesh the file: " + outcome.report;
    case ChildOutcome::End::finished:
      break;
  }
  return "Gmsh gave no mesh";
}

// The text of the child's mesh file, refused when it is larger than a boundary within
// the element limit can make (about 50 B per element and node: 1 kB each allowed).
std::string read_child_mesh(const std::filesystem::path& mesh, const std::filesystem::path& file,
                            const ResourceLimits& limits) {
  std::error_code error;
  const auto size = std::filesystem::file_size(mesh, error);
  const double most = 1e6 + 1e3 * static_cast<double>(limits.max_elements);
  if (error || static_cast<double>(size) > most)
    throw InputError(SourceLocation{file.string(), 0, ""},
                     "Gmsh's mesh of the file takes " + format_bytes(static_cast<double>(size)) +
                         ", more than a boundary of at most " + std::to_string(limits.max_elements) +
                         " elements can: check the element counts and mesh sizes, or raise --max-elements");
  std::ifstream in(mesh, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
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

GmshCurves mesh_geo(const std::filesystem::path& file, const GmshOptions& options) {
#ifdef BEMCONTACT_WITH_GMSH
  const GmshApi& api = gmsh_library();  // opened here, in this process: the child finds it loaded
  if (!api.failure.empty())
    throw InputError(SourceLocation{file.string(), 0, ""},
                     "reading a .geo file needs the Gmsh library (" + api.failure + "; apt-get install libgmsh4.8), "
                     "or mesh it with gmsh -1 " + file.filename().string() + " -format msh41 and give the .msh file");
  // Gmsh runs in a child process: it cannot be interrupted, ends its process on
  // std::bad_alloc in its threads, keeps global state and sets OpenMP's thread count; the
  // child is bounded in time and memory and takes all of that with it (io/child_process.hpp).
  const TemporaryMesh mesh;
  const auto arguments = gmsh_arguments(options);
  const ChildLimits limits{options.limits.gmsh_timeout_seconds, gmsh_meshing_bytes(options.limits)};
  const ChildOutcome outcome =
      run_in_child([&](int report_fd) { return mesh_into(api, file, mesh.path, arguments, report_fd); }, limits);
  if (outcome.end != ChildOutcome::End::finished)
    throw InputError(SourceLocation{file.string(), 0, ""}, meshing_failure(outcome, options));
  const std::string text = read_child_mesh(mesh.path, file, options.limits);
  try {
    return parse_msh(text, file.string(), options.limits.max_elements);
  } catch (const InputError& e) {
    // The lines are those of Gmsh's mesh, not of the .geo file.
    throw InputError(SourceLocation{file.string(), 0, ""}, "Gmsh's mesh of the file: " + e.detail());
  }
#else
  (void)options;
  throw InputError(SourceLocation{file.string(), 0, ""},
                   "this build of bemcontact reads .geo files only with the Gmsh library (libgmsh-dev, CMake "
                   "option BEMCONTACT_WITH_GMSH); mesh it with gmsh -1 " + file.filename().string() +
                       " -format msh41 and give the .msh file");
#endif
}

GmshBoundary read_gmsh_boundary(const std::filesystem::path& file, bool axisymmetric, const GmshOptions& options) {
  const std::string extension = file.extension().string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    throw InputError(SourceLocation{file.string(), 0, ""},
                     std::filesystem::exists(file, error) ? "the Gmsh file is not a regular file"
                                                          : "cannot read the Gmsh file: no such file");
  if (extension == ".geo") return boundary_from_curves(mesh_geo(file, options), axisymmetric, file.string());
  if (extension == ".msh") {
    // The text and its lines take about 4 times the file's size.
    const double size = static_cast<double>(std::filesystem::file_size(file, error));
    if (4.0 * size > options.limits.memory_limit_bytes())
      throw InputError(SourceLocation{file.string(), 0, ""},
                       "the .msh file takes " + format_bytes(size) + "; reading it would need about " +
                           format_bytes(4.0 * size) + " of memory, over the limit of " +
                           format_bytes(options.limits.memory_limit_bytes()) + " (raise it with --max-memory)");
    return boundary_from_curves(parse_msh(read_problem_text(file), file.string(), options.limits.max_elements),
                                axisymmetric, file.string());
  }
  throw InputError(SourceLocation{file.string(), 0, ""}, "a Gmsh geometry is a .geo or .msh file, found '" +
                                                             file.filename().string() + "'");
}

}  // namespace bemcontact::io
