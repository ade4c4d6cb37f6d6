#include "bemcontact/geometry/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace bemcontact::geometry {

BoundaryElement straight_element(const Vec2& start, const Vec2& end) {
  BoundaryElement e;
  e.start = start;
  e.end = end;
  const Vec2 d = end - start;
  e.length = d.norm();
  e.tangent = d / e.length;
  e.normal = Vec2(e.tangent.y(), -e.tangent.x());
  return e;
}

double BoundaryElement::shape_derivative(int a, double f) const {
  if (node_count == 1) return 0.0;
  double sum = 0.0;
  for (int c = 0; c < node_count; ++c) {
    if (c == a) continue;
    double term = 1.0 / (node_fraction[a] - node_fraction[c]);
    for (int b = 0; b < node_count; ++b)
      if (b != a && b != c) term *= (f - node_fraction[b]) / (node_fraction[a] - node_fraction[b]);
    sum += term;
  }
  return sum;
}

Vec2 BoundaryElement::point(double f) const {
  if (!arc) return start + f * (end - start);
  const double angle = angle_start + f * angle_span;
  return center + radius * Vec2(std::cos(angle), std::sin(angle));
}

Vec2 BoundaryElement::normal_at(double f) const {
  if (!arc) return normal;
  // Travel along +angle (ccw) has the domain on the left, so the outward normal is the
  // radial direction; clockwise travel points it to the centre.
  const double angle = angle_start + f * angle_span;
  const Vec2 radial(std::cos(angle), std::sin(angle));
  return angle_span > 0.0 ? radial : Vec2(-radial);
}

bool lies_on_axis(const BoundaryPiece& piece, double tolerance) {
  return piece.shape == PieceShape::line && std::abs(piece.start.x()) <= tolerance &&
         std::abs(piece.end.x()) <= tolerance;
}

namespace {

Vec2 tangent_of(const Vec2& outward_normal) { return Vec2(-outward_normal.y(), outward_normal.x()); }

struct VertexPlan {
  int piece_in = -1, piece_out = -1;
  bool in_meshed = false, out_meshed = false;
  bool split = false;
  Index shared_node = -1;
};

// Pieces chain within a tolerance; snap each start onto the previous end so that shared
// vertices are bit-identical (the near-singular integrals see any gap).
std::vector<BoundaryPiece> chained_pieces(const std::vector<BoundaryPiece>& input_pieces,
                                          const std::vector<Contour>& contours, const MeshOptions& options) {
  std::vector<BoundaryPiece> pieces = input_pieces;
  if (options.skip_axis_pieces) {
    // Points on the axis must have r exactly 0: the ring kernels treat r = 0 specially.
    const double axis_tolerance = 1e-9 * geometry_scale(input_pieces);
    for (auto& piece : pieces)
      for (Vec2* point : {&piece.start, &piece.end})
        if (std::abs(point->x()) <= axis_tolerance) point->x() = 0.0;
  }
  for (const auto& contour : contours)
    for (std::size_t k = 0; k < contour.pieces.size(); ++k)
      pieces[contour.pieces[(k + 1) % contour.pieces.size()]].start = pieces[contour.pieces[k]].end;
  return pieces;
}

// The mesh's tables per piece, the pieces left without elements (symmetry lines, the axis)
// and the symmetry images.
void describe_pieces(BoundaryMesh& mesh, const std::vector<BoundaryPiece>& pieces, const MeshOptions& options) {
  const double tol = 1e-9 * mesh.scale;
  const int piece_count = static_cast<int>(pieces.size());
  mesh.piece_elements.assign(piece_count, {});
  mesh.piece_nodes.assign(piece_count, {});
  mesh.piece_skipped.assign(piece_count, false);
  for (const auto& piece : pieces) mesh.piece_names.push_back(piece.name);
  for (int p = 0; p < piece_count; ++p)
    mesh.piece_skipped[p] = pieces[p].symmetry || (options.skip_axis_pieces && lies_on_axis(pieces[p], tol));
  mesh.images = symmetry_images(pieces, options.skip_axis_pieces);
  for (const auto& piece : pieces)
    if (piece.symmetry) mesh.symmetry_segments.push_back(straight_element(piece.start, piece.end));
}

// The end elements' lengths the corner transition grades each piece toward (none: not
// graded at that end).
struct EndCaps {
  std::vector<double> start, end;
};
constexpr double kNoCap = std::numeric_limits<double>::infinity();

// One pass over the vertices: caps the coarser end of every pair of end elements differing
// by more than `trigger`. True when a cap changed.
bool cap_coarse_ends(const BoundaryMesh& mesh, const std::vector<BoundaryPiece>& pieces,
                     const std::vector<std::vector<double>>& breakpoints, double trigger, EndCaps& caps) {
  auto end_length = [&](int p, bool at_start) {
    const auto& s = breakpoints[p];
    return piece_length(pieces[p]) * (at_start ? s[1] - s[0] : s.back() - s[s.size() - 2]);
  };
  bool changed = false;
  for (const auto& contour : mesh.contours) {
    const std::size_t m = contour.pieces.size();
    for (std::size_t k = 0; k < m; ++k) {
      const int in = contour.pieces[(k + m - 1) % m], out = contour.pieces[k];
      if (mesh.piece_skipped[in] || mesh.piece_skipped[out] || in == out) continue;
      const double h_in = end_length(in, false), h_out = end_length(out, true);
      if (h_in > trigger * h_out && !pieces[in].fixed_mesh && h_out < caps.end[in]) {
        caps.end[in] = h_out;
        changed = true;
      }
      if (h_out > trigger * h_in && !pieces[out].fixed_mesh && h_in < caps.start[out]) {
        caps.start[out] = h_in;
        changed = true;
      }
    }
  }
  return changed;
}

// The corner transition: grades the pieces toward vertices where a much finer piece meets
// them, and lists the graded pieces in mesh.transitions.
void grade_toward_finer_neighbours(BoundaryMesh& mesh, const std::vector<BoundaryPiece>& pieces, double growth,
                                   std::vector<std::vector<double>>& breakpoints) {
  const int piece_count = static_cast<int>(pieces.size());
  const double trigger = std::max(2.0, growth);  // end elements differing by up to 2x are left alone
  EndCaps caps{std::vector<double>(piece_count, kNoCap), std::vector<double>(piece_count, kNoCap)};
  // A graded piece may in turn be much finer than its other neighbour: repeat until no
  // cap changes (caps only shrink, toward the finest element, so this ends).
  for (int pass = 0; pass < 4 * piece_count + 4; ++pass) {
    if (!cap_coarse_ends(mesh, pieces, breakpoints, trigger, caps)) break;
    for (int p = 0; p < piece_count; ++p)
      if (caps.start[p] != kNoCap || caps.end[p] != kNoCap)
        breakpoints[p] = transition_breakpoints(pieces[p], caps.start[p], caps.end[p], growth);
  }
  for (int p = 0; p < piece_count; ++p) {
    if (caps.start[p] == kNoCap && caps.end[p] == kNoCap) continue;
    mesh.transitions.push_back({p, pieces[p].name, pieces[p].elements, static_cast<int>(breakpoints[p].size()) - 1});
  }
}

// Element end points of each piece, with the corner transition toward vertices where a
// much finer piece meets it (a coarse element next to a fine one spoils the nodes of the
// fine side near the vertex: measured in docs/corners.md).
std::vector<std::vector<double>> piece_breakpoints(BoundaryMesh& mesh, const std::vector<BoundaryPiece>& pieces,
                                                   const MeshOptions& options) {
  std::vector<std::vector<double>> breakpoints(pieces.size());
  for (std::size_t p = 0; p < pieces.size(); ++p) breakpoints[p] = element_breakpoints(pieces[p]);
  if (options.corner_transition > 1.0)
    grade_toward_finer_neighbours(mesh, pieces, options.corner_transition, breakpoints);
  return breakpoints;
}

// Plan each vertex: the start of every piece, joined to the end of the previous one.
std::vector<VertexPlan> plan_vertices(const BoundaryMesh& mesh, const std::vector<BoundaryPiece>& pieces,
                                      const MeshOptions& options) {
  // Linear and quadratic elements have nodes at their ends (split at corners).
  const bool end_nodes = options.interpolation != Interpolation::constant;
  std::vector<VertexPlan> start_vertex(pieces.size());
  for (const auto& contour : mesh.contours) {
    const std::size_t m = contour.pieces.size();
    for (std::size_t k = 0; k < m; ++k) {
      const int in = contour.pieces[(k + m - 1) % m], out = contour.pieces[k];
      VertexPlan& plan = start_vertex[out];
      plan.piece_in = in;
      plan.piece_out = out;
      plan.in_meshed = !mesh.piece_skipped[in];
      plan.out_meshed = !mesh.piece_skipped[out];
      // Next to a symmetry line the node moves into its element: a node on the line would
      // coincide with its own image.
      if (end_nodes && (pieces[in].symmetry || pieces[out].symmetry)) plan.split = true;
      if (plan.in_meshed && plan.out_meshed && end_nodes) {
        const Vec2 t_in = tangent_of(point_on_piece(pieces[in], 1.0).outward_normal);
        const Vec2 t_out = tangent_of(point_on_piece(pieces[out], 0.0).outward_normal);
        const double turn = std::atan2(t_in.x() * t_out.y() - t_in.y() * t_out.x(), t_in.dot(t_out));
        plan.split = std::abs(turn) > options.split_angle_radians ||
                     pieces[in].condition_signature != pieces[out].condition_signature;
      }
    }
  }
  return start_vertex;
}

// The piece after p in its contour: its start vertex is the vertex at the end of p.
int next_piece(const Contour& contour, int p) {
  int next = -1;
  for (std::size_t k = 0; k < contour.pieces.size(); ++k)
    if (contour.pieces[k] == p) next = contour.pieces[(k + 1) % contour.pieces.size()];
  return next;
}

// The piece's points at its element end points, its ends exactly its vertices.
std::vector<PiecePoint> element_end_points(const BoundaryPiece& piece, const std::vector<double>& s) {
  const int n = static_cast<int>(s.size()) - 1;
  std::vector<PiecePoint> points(n + 1);
  for (int k = 0; k <= n; ++k) points[k] = point_on_piece(piece, s[k]);
  points[0].position = piece.start;
  points[n].position = piece.end;
  return points;
}

// A piece being meshed: its element end points and the plans of its two vertices.
struct PieceToMesh {
  const BoundaryPiece& piece;
  int index;
  const std::vector<double>& s;     // element end points, as fractions of the piece
  std::vector<PiecePoint> points;   // the piece's points there
  VertexPlan& first;                // the vertex at its start
  VertexPlan& last;                 // the vertex at its end
};

Index add_node(BoundaryMesh& mesh, const Vec2& position, const Vec2& normal, int piece, bool shifted) {
  mesh.nodes.push_back({position, normal, piece, shifted});
  return static_cast<Index>(mesh.nodes.size() - 1);
}

// Element k of the piece: the chord, or on an arc with quadratic elements the exact arc.
BoundaryElement piece_element(const PieceToMesh& run, int k, bool quadratic) {
  BoundaryElement element = straight_element(run.points[k].position, run.points[k + 1].position);
  element.piece = run.index;
  const BoundaryPiece& piece = run.piece;
  if (quadratic && piece.shape == PieceShape::arc) {
    // The exact arc: the element's parameter runs linearly in angle, as the piece's.
    const Vec2 a = piece.start - piece.center;
    const double sweep = arc_sweep(piece);
    element.arc = true;
    element.center = piece.center;
    element.radius = arc_radius(piece);
    element.angle_start = std::atan2(a.y(), a.x()) + run.s[k] * sweep;
    element.angle_span = (run.s[k + 1] - run.s[k]) * sweep;
  }
  return element;
}

// A shifted node on an arc's chord stands for the arc point at the same parameter: it takes
// that point's normal, so tractions and stresses are resolved on the true surface (on a
// line both normals agree).
Vec2 shifted_normal(const PieceToMesh& run, int k, double fraction) {
  return point_on_piece(run.piece, run.s[k] + fraction * (run.s[k + 1] - run.s[k])).outward_normal;
}

// A shifted node of a quadratic element lies on the true geometry; of a linear one, on the
// chord (with the true normal, above).
Vec2 shifted_position(const BoundaryElement& element, double fraction, bool quadratic) {
  const Vec2 d = element.end - element.start;
  return quadratic ? element.point(fraction) : Vec2(element.start + fraction * d);
}

// The start node of element k: shifted into the element at a split vertex (every element's
// when discontinuous), else the previous element's end node, or the node at the vertex,
// shared with the previous piece.
Index start_node(BoundaryMesh& mesh, const MeshOptions& options, PieceToMesh& run, BoundaryElement& element, int k,
                 Index previous_end) {
  const bool quadratic = options.interpolation == Interpolation::quadratic;
  Index node = -1;
  if (options.discontinuous || (k == 0 && run.first.split)) {
    element.node_fraction[0] = options.corner_shift;
    node = add_node(mesh, shifted_position(element, options.corner_shift, quadratic),
                    shifted_normal(run, k, options.corner_shift), run.index, true);
  } else if (k > 0) {
    return previous_end;
  } else if (run.first.in_meshed && run.first.shared_node >= 0) {
    node = run.first.shared_node;
  } else {
    node = add_node(mesh, element.start, run.points[0].outward_normal, run.index, false);
    if (run.first.in_meshed) run.first.shared_node = node;
  }
  mesh.piece_nodes[run.index].push_back(node);
  return node;
}

// The end node of element k, as its start node: shifted at a split vertex, else at the
// element's end (shared with the next piece at the last vertex).
Index end_node(BoundaryMesh& mesh, const MeshOptions& options, PieceToMesh& run, BoundaryElement& element, int k) {
  const bool quadratic = options.interpolation == Interpolation::quadratic;
  const int n = static_cast<int>(run.s.size()) - 1;
  Index node = -1;
  if (options.discontinuous || (k + 1 == n && run.last.split)) {
    element.node_fraction[1] = 1.0 - options.corner_shift;
    node = add_node(mesh, shifted_position(element, 1.0 - options.corner_shift, quadratic),
                    shifted_normal(run, k, 1.0 - options.corner_shift), run.index, true);
  } else if (k + 1 < n) {
    node = add_node(mesh, element.end, run.points[k + 1].outward_normal, run.index, false);
  } else if (run.last.out_meshed && run.last.shared_node >= 0) {
    node = run.last.shared_node;
  } else {
    node = add_node(mesh, element.end, run.points[n].outward_normal, run.index, false);
    if (run.last.out_meshed) run.last.shared_node = node;
  }
  mesh.piece_nodes[run.index].push_back(node);
  return node;
}

// The elements of one piece and their nodes, in order.
void mesh_piece(BoundaryMesh& mesh, const MeshOptions& options, PieceToMesh& run) {
  // Linear and quadratic elements have nodes at their ends (split at corners).
  const bool end_nodes = options.interpolation != Interpolation::constant;
  const bool quadratic = options.interpolation == Interpolation::quadratic;
  const int p = run.index;
  const int n = static_cast<int>(run.s.size()) - 1;
  Index previous_end = -1;
  for (int k = 0; k < n; ++k) {
    BoundaryElement element = piece_element(run, k, quadratic);
    const Index e = static_cast<Index>(mesh.elements.size());
    if (!end_nodes) {
      element.node_count = 1;
      element.node_fraction = {0.5, 0.5, 0.5};
      element.nodes[0] = add_node(mesh, 0.5 * (element.start + element.end), element.normal, p, false);
      mesh.piece_nodes[p].push_back(element.nodes[0]);
    } else {
      element.node_count = quadratic ? 3 : 2;
      element.nodes[0] = start_node(mesh, options, run, element, k, previous_end);
      if (quadratic) {  // middle node, on the true geometry
        element.nodes[2] = add_node(mesh, element.point(0.5), element.normal_at(0.5), p, false);
        mesh.piece_nodes[p].push_back(element.nodes[2]);
      }
      element.nodes[1] = end_node(mesh, options, run, element, k);
      previous_end = element.nodes[1];
    }
    mesh.elements.push_back(element);
    mesh.piece_elements[p].push_back(e);
  }
}

// Vertices, for point constraints and output.
void add_vertices(BoundaryMesh& mesh, const std::vector<BoundaryPiece>& pieces,
                  const std::vector<VertexPlan>& start_vertex) {
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const VertexPlan& plan = start_vertex[p];
    MeshVertex vertex;
    vertex.position = pieces[p].start;
    vertex.piece_in = plan.piece_in;
    vertex.piece_out = plan.piece_out;
    vertex.split = plan.split;
    if (plan.piece_in >= 0) vertex.normal_in = point_on_piece(pieces[plan.piece_in], 1.0).outward_normal;
    vertex.normal_out = point_on_piece(pieces[p], 0.0).outward_normal;
    if (plan.in_meshed && !mesh.piece_elements[plan.piece_in].empty())
      vertex.element_in = mesh.piece_elements[plan.piece_in].back();
    if (plan.out_meshed && !mesh.piece_elements[p].empty())
      vertex.element_out = mesh.piece_elements[p].front();
    mesh.vertices.push_back(vertex);
  }
}

}  // namespace

double discontinuous_node_fraction(Interpolation interpolation) {
  return interpolation == Interpolation::quadratic ? 0.5 * (1.0 - std::sqrt(0.6)) : 0.5 * (1.0 - 1.0 / std::sqrt(3.0));
}

void use_discontinuous_elements(MeshOptions& options) {
  options.discontinuous = true;
  options.corner_shift = discontinuous_node_fraction(options.interpolation);
}

BoundaryMesh mesh_boundary(const std::vector<BoundaryPiece>& input_pieces, const MeshOptions& options) {
  if (!(options.corner_shift > 0.0 && options.corner_shift < 0.5))
    throw GeometryError("corner_shift must lie in (0, 0.5), got " +
                        std::to_string(options.corner_shift));
  BoundaryMesh mesh;
  mesh.contours = build_contours(input_pieces);
  const std::vector<BoundaryPiece> pieces = chained_pieces(input_pieces, mesh.contours, options);
  mesh.scale = geometry_scale(pieces);
  describe_pieces(mesh, pieces, options);
  const auto breakpoints = piece_breakpoints(mesh, pieces, options);
  std::vector<VertexPlan> start_vertex = plan_vertices(mesh, pieces, options);
  for (const auto& contour : mesh.contours)
    for (const int p : contour.pieces) {
      if (mesh.piece_skipped[p]) continue;
      PieceToMesh piece{pieces[p], p, breakpoints[p], element_end_points(pieces[p], breakpoints[p]),
                        start_vertex[p], start_vertex[next_piece(contour, p)]};
      mesh_piece(mesh, options, piece);
    }
  add_vertices(mesh, pieces, start_vertex);
  return mesh;
}

std::vector<BoundaryPiece> pieces_with_nodes_at(const BoundaryMesh& mesh, std::vector<BoundaryPiece> pieces,
                                                const std::vector<Vec2>& points, double tolerance, double snap) {
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (mesh.piece_skipped[p] || mesh.piece_elements[p].empty() || pieces[p].shape != PieceShape::line) continue;
    BoundaryPiece& piece = pieces[p];
    const double length = piece_length(piece);
    const auto fraction_at = [&](const Vec2& x) { return arc_length_at(piece, x) / length; };
    // The mesh's own end points, and the points on the piece's elements.
    std::vector<double> ends{0.0};
    std::vector<double> wanted;
    for (const Index e : mesh.piece_elements[p]) {
      const auto& element = mesh.elements[static_cast<std::size_t>(e)];
      ends.push_back(fraction_at(element.end));
      const Vec2 d = element.end - element.start;
      for (const Vec2& x : points) {
        const double f = std::clamp((x - element.start).dot(d) / d.squaredNorm(), 0.0, 1.0);
        if ((x - (element.start + f * d)).norm() <= tolerance) wanted.push_back(fraction_at(x));
      }
    }
    ends.back() = 1.0;
    std::sort(wanted.begin(), wanted.end());
    std::vector<char> moved(ends.size(), 0);
    std::vector<double> placed;
    for (const double w : wanted) {
      // The element holding w, its length, and the nearer of its ends.
      const std::size_t k = static_cast<std::size_t>(
          std::clamp<std::ptrdiff_t>(std::upper_bound(ends.begin(), ends.end(), w) - ends.begin(), 1,
                                     static_cast<std::ptrdiff_t>(ends.size()) - 1));
      const double h = ends[k] - ends[k - 1];
      const std::size_t nearer = w - ends[k - 1] < ends[k] - w ? k - 1 : k;
      const double gap = std::abs(w - ends[nearer]);
      if (gap <= 1e-9) continue;  // already an end point
      const bool near_placed = std::any_of(placed.begin(), placed.end(), [&](double q) { return std::abs(q - w) < snap * h; });
      if (near_placed) continue;
      if (gap < snap * h) {
        if (nearer == 0 || nearer + 1 == ends.size() || moved[nearer]) continue;
        ends[nearer] = w;
        moved[nearer] = 1;
      } else {
        ends.insert(ends.begin() + static_cast<std::ptrdiff_t>(k), w);
        moved.insert(moved.begin() + static_cast<std::ptrdiff_t>(k), 1);
      }
      placed.push_back(w);
    }
    piece.breakpoints = ends;
  }
  return pieces;
}

std::vector<std::string> mesh_quality_warnings(const BoundaryMesh& mesh, double ratio) {
  // Worst ratio per piece (inside it) and per vertex (across it), in contour order.
  struct Finding {
    double ratio = 0.0;
    Vec2 where = Vec2::Zero();
    std::string text;
  };
  std::vector<Finding> findings;
  auto note = [&](const std::string& text, double r, const Vec2& where) {
    for (auto& f : findings)
      if (f.text == text) {
        if (r > f.ratio) f.ratio = r, f.where = where;
        return;
      }
    findings.push_back({r, where, text});
  };
  for (const auto& contour : mesh.contours) {
    const std::size_t m = contour.pieces.size();
    for (std::size_t k = 0; k < m; ++k) {
      const int p = contour.pieces[k];
      const auto& elements = mesh.piece_elements[p];
      for (std::size_t e = 0; e + 1 < elements.size(); ++e) {
        const auto& a = mesh.elements[elements[e]];
        const auto& b = mesh.elements[elements[e + 1]];
        const double r = std::max(a.length, b.length) / std::min(a.length, b.length);
        if (r > ratio) note("boundary '" + mesh.piece_names[p] + "'", r, a.end);
      }
      const int next = contour.pieces[(k + 1) % m];
      if (next == p || elements.empty() || mesh.piece_elements[next].empty()) continue;
      const auto& a = mesh.elements[elements.back()];
      const auto& b = mesh.elements[mesh.piece_elements[next].front()];
      const double r = std::max(a.length, b.length) / std::min(a.length, b.length);
      if (r > ratio)
        note("the vertex between boundaries '" + mesh.piece_names[p] + "' and '" + mesh.piece_names[next] + "'", r,
             a.end);
    }
  }
  std::vector<std::string> messages;
  for (const auto& f : findings) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, " at (%.6g, %.6g)", f.where.x(), f.where.y());
    char r[32];
    std::snprintf(r, sizeof r, "%.3g", f.ratio);
    messages.push_back("mesh: neighbouring elements differ in length by a factor " + std::string(r) + " on " +
                       f.text + buffer + " (above " + std::to_string(static_cast<int>(ratio)) +
                       "; a coarse element next to fine ones spoils the results near it: grade the coarser "
                       "boundary toward the finer one, as [mesh] corner_transition does at vertices)");
  }
  return messages;
}

Index find_node_at(const BoundaryMesh& mesh, const Vec2& point, double tolerance) {
  Index best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < mesh.node_count(); ++i) {
    const double distance = (mesh.nodes[i].position - point).norm();
    if (distance <= tolerance && distance < best_distance) {
      best = i;
      best_distance = distance;
    }
  }
  return best;
}

Index find_vertex_at(const BoundaryMesh& mesh, const Vec2& point, double tolerance) {
  for (Index v = 0; v < static_cast<Index>(mesh.vertices.size()); ++v)
    if ((mesh.vertices[v].position - point).norm() <= tolerance) return v;
  return -1;
}

}  // namespace bemcontact::geometry
