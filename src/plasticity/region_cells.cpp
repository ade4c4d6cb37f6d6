#include "bemcontact/plasticity/region_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>

#include "bemcontact/core/error.hpp"
#include "bemcontact/plasticity/edge_quadrature.hpp"

namespace bemcontact::plasticity {

namespace {

struct Rect {
  Vec2 lo, hi;
  int depth = 0;
  Vec2 centre() const { return 0.5 * (lo + hi); }
  double longer_side() const { return std::max(hi.x() - lo.x(), hi.y() - lo.y()); }
};


double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) twice += cross(polygon[k], polygon[(k + 1) % polygon.size()]);
  return 0.5 * twice;
}

// The target edge at the rectangle: `size`, or less near a refinement point.
double target_size(const Rect& r, const CellMeshOptions& options) {
  double h = options.size;
  for (const Vec2& p : options.refine_points) {
    const Vec2 nearest = p.cwiseMax(r.lo).cwiseMin(r.hi);
    h = std::min(h, options.refine_size + options.growth * (p - nearest).norm());
  }
  return h;
}

// Whether the segment a-b meets the closed rectangle (Liang-Barsky).
bool segment_meets(const Vec2& a, const Vec2& b, const Rect& r, double eps) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  for (int k = 0; k < 2; ++k) {
    const double lo = r.lo[k] - eps - a[k], hi = r.hi[k] + eps - a[k];
    if (std::abs(d[k]) < std::numeric_limits<double>::min()) {
      if (lo > 0.0 || hi < 0.0) return false;
      continue;
    }
    double ta = lo / d[k], tb = hi / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Even-odd rule over every loop.
bool inside_region(const Vec2& p, const std::vector<RegionLoop>& loops) {
  bool inside = false;
  for (const auto& loop : loops)
    for (std::size_t k = 0, n = loop.points.size(); k < n; ++k) {
      const Vec2 &a = loop.points[k], &b = loop.points[(k + 1) % n];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          p.x() < a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x()))
        inside = !inside;
    }
  return inside;
}

// Sutherland-Hodgman: the polygon clipped to the rectangle, one side at a time.
std::vector<Vec2> clip_to(std::vector<Vec2> polygon, const Rect& r, double eps) {
  for (int side = 0; side < 4 && !polygon.empty(); ++side) {
    const int axis = side / 2;
    const bool lower = side % 2 == 0;
    const double bound = lower ? r.lo[axis] : r.hi[axis];
    const auto inside = [&](const Vec2& p) { return lower ? p[axis] >= bound - eps : p[axis] <= bound + eps; };
    std::vector<Vec2> out;
    for (std::size_t k = 0, n = polygon.size(); k < n; ++k) {
      const Vec2 &prev = polygon[(k + n - 1) % n], &cur = polygon[k];
      const bool in_cur = inside(cur), in_prev = inside(prev);
      if (in_cur != in_prev) {
        const double t = (bound - prev[axis]) / (cur[axis] - prev[axis]);
        Vec2 x = prev + t * (cur - prev);
        x[axis] = bound;
        out.push_back(x);
      }
      if (in_cur) out.push_back(cur);
    }
    polygon = std::move(out);
  }
  return polygon;
}

// Without repeated points and straight-through vertices (a fan from such a vertex would put
// mean points on the cell's own edge).
std::vector<Vec2> cleaned(std::vector<Vec2> polygon, double eps) {
  bool changed = true;
  while (changed && polygon.size() >= 3) {
    changed = false;
    for (std::size_t k = 0, n = polygon.size(); k < n; ++k) {
      const Vec2 &prev = polygon[(k + n - 1) % n], &cur = polygon[k], &next = polygon[(k + 1) % n];
      const Vec2 a = cur - prev, b = next - cur;
      if (a.norm() < eps || std::abs(cross(a, b)) <= eps * (a.norm() + b.norm())) {
        polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
        break;
      }
    }
  }
  return polygon;
}

// How many times the region's boundary enters the leaf: the runs of the clipped polygon's
// edges that do not lie on the leaf's sides. More than one: the leaf holds several pieces of
// the region (or one joined through the leaf's side), which one polygon cannot carry.
int boundary_entries(const std::vector<Vec2>& polygon, const Rect& r, double eps) {
  const std::size_t n = polygon.size();
  const auto on_side = [&](std::size_t k) {
    const Vec2 &a = polygon[k], &b = polygon[(k + 1) % n];
    for (int axis = 0; axis < 2; ++axis)
      for (double bound : {r.lo[axis], r.hi[axis]})
        if (std::abs(a[axis] - bound) <= eps && std::abs(b[axis] - bound) <= eps) return true;
    return false;
  };
  int entries = 0;
  for (std::size_t k = 0; k < n; ++k) entries += !on_side(k) && on_side((k + n - 1) % n);
  return entries;
}

// The leaves' polygon vertices by square buckets of `width`, to find those lying on an edge.
class VertexBuckets {
 public:
  VertexBuckets(const std::vector<Cell>& polygons, const Vec2& origin, double width) : origin_(origin), width_(width) {
    for (const auto& polygon : polygons)
      for (const Vec2& v : polygon.vertices) buckets_[key(bucket(v.x(), 0), bucket(v.y(), 1))].push_back(v);
  }
  // The vertices strictly inside the segment a-b (within eps of it), from a to b.
  std::vector<Vec2> on_segment(const Vec2& a, const Vec2& b, double eps) const {
    std::vector<Vec2> out;
    const Vec2 d = b - a;
    const double length = d.norm();
    const long long i0 = bucket(std::min(a.x(), b.x()) - eps, 0), i1 = bucket(std::max(a.x(), b.x()) + eps, 0);
    const long long j0 = bucket(std::min(a.y(), b.y()) - eps, 1), j1 = bucket(std::max(a.y(), b.y()) + eps, 1);
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > 4 * (static_cast<long long>(length / width_) + 4)) return out;  // not a leaf side
    for (long long i = i0; i <= i1; ++i)
      for (long long j = j0; j <= j1; ++j) {
        const auto found = buckets_.find(key(i, j));
        if (found == buckets_.end()) continue;
        for (const Vec2& v : found->second) {
          const double t = (v - a).dot(d) / (length * length);
          if (t * length > eps && (1.0 - t) * length > eps && std::abs(cross(d, v - a)) <= eps * length &&
              std::none_of(out.begin(), out.end(), [&](const Vec2& w) { return (w - v).norm() <= eps; }))
            out.push_back(v);
        }
      }
    std::sort(out.begin(), out.end(), [&](const Vec2& p, const Vec2& q) { return (p - a).dot(d) < (q - a).dot(d); });
    return out;
  }

 private:
  long long bucket(double x, int axis) const { return static_cast<long long>(std::floor((x - origin_[axis]) / width_)); }
  static long long key(long long i, long long j) { return i * 4000037LL + j; }
  Vec2 origin_;
  double width_;
  std::unordered_map<long long, std::vector<Vec2>> buckets_;
};

// A leaf's cell, or with `crossed` its fan of triangles about its own vertices' mean (the
// rectangle's diagonals for a whole leaf), through the vertices of smaller neighbours that
// lie on its sides: the triangles then meet vertex to vertex, so a continuous piecewise
// linear displacement has a constant strain on each (a compatible plastic strain). A
// concave cut stays whole (its fan would leave it).
void add_cell(std::vector<Cell>& cells, Cell cell, bool crossed, const VertexBuckets& vertices, double eps) {
  if (!crossed || !cell.convex()) {
    cells.push_back(std::move(cell));
    return;
  }
  Vec2 centre = Vec2::Zero();
  for (const Vec2& v : cell.vertices) centre += v;
  centre /= static_cast<double>(cell.vertices.size());
  std::vector<Vec2> polygon;
  for (std::size_t k = 0, n = cell.vertices.size(); k < n; ++k) {
    polygon.push_back(cell.vertices[k]);
    for (const Vec2& v : vertices.on_segment(cell.vertices[k], cell.vertices[(k + 1) % n], eps)) polygon.push_back(v);
  }
  for (std::size_t k = 0, n = polygon.size(); k < n; ++k) cells.push_back(Cell{{polygon[k], polygon[(k + 1) % n], centre}});
}

}  // namespace

std::vector<Cell> region_cells(const std::vector<RegionLoop>& loops, const CellMeshOptions& options) {
  if (!(options.size > 0.0)) throw Error("the cell size must be > 0");
  const bool graded = !options.refine_points.empty();
  if (graded && !(options.refine_size > 0.0 && options.refine_size <= options.size))
    throw Error("the refined cell size must be > 0 and at most the cell size");
  if (graded && !(options.growth > 0.0)) throw Error("the cells' growth away from a refinement point must be > 0");
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& loop : loops)
    for (const Vec2& p : loop.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (loops.empty() || !(hi.x() > lo.x() && hi.y() > lo.y())) throw Error("the region has no area to put cells in");
  const double eps = 1e-10 * (hi - lo).norm();
  if (options.box) {
    const auto& [box_lo, box_hi] = *options.box;
    if (!(box_hi.x() > box_lo.x() && box_hi.y() > box_lo.y()))
      throw Error("the cells' box must have its upper-right corner above and right of its lower-left one");
    lo = lo.cwiseMax(box_lo), hi = hi.cwiseMin(box_hi);
    if (!(hi.x() > lo.x() + eps && hi.y() > lo.y() + eps))
      throw Error("the cells' box " + point_text(box_lo) + " - " + point_text(box_hi) + " does not meet the region");
  }

  // The quadtree: a grid of about `size`, each leaf split in four toward the points.
  const int nx = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / options.size - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / options.size - 1e-9)));
  if (static_cast<double>(nx) * ny > static_cast<double>(options.max_cells))
    throw Error("cells of size " + std::to_string(options.size) + " would be more than " +
                std::to_string(options.max_cells) + ": give a larger size or a box");
  std::vector<Rect> stack, leaves;
  const Vec2 step((hi.x() - lo.x()) / nx, (hi.y() - lo.y()) / ny);
  for (int j = ny - 1; j >= 0; --j)
    for (int i = nx - 1; i >= 0; --i) {
      const Vec2 a = lo + Vec2(i * step.x(), j * step.y());
      stack.push_back(Rect{a, a + step, 0});
    }
  while (!stack.empty()) {
    const Rect r = stack.back();
    stack.pop_back();
    if (r.depth < 20 && r.longer_side() > 1.0001 * target_size(r, options)) {
      const Vec2 m = r.centre();
      stack.push_back(Rect{Vec2(m.x(), m.y()), r.hi, r.depth + 1});
      stack.push_back(Rect{Vec2(r.lo.x(), m.y()), Vec2(m.x(), r.hi.y()), r.depth + 1});
      stack.push_back(Rect{Vec2(m.x(), r.lo.y()), Vec2(r.hi.x(), m.y()), r.depth + 1});
      stack.push_back(Rect{r.lo, m, r.depth + 1});
      continue;
    }
    leaves.push_back(r);
    if (static_cast<Index>(leaves.size()) > options.max_cells)
      throw Error("the cells would be more than " + std::to_string(options.max_cells) +
                  ": give a larger size or refine_size, or a box");
  }

  std::vector<Cell> polygons;  // one per leaf in the region
  for (const Rect& r : leaves) {
    std::vector<int> cutting;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const auto& points = loops[l].points;
      for (std::size_t k = 0, n = points.size(); k < n; ++k)
        if (segment_meets(points[k], points[(k + 1) % n], r, eps)) {
          cutting.push_back(static_cast<int>(l));
          break;
        }
    }
    if (cutting.empty()) {
      if (inside_region(r.centre(), loops))
        polygons.push_back(Cell{{r.lo, Vec2(r.hi.x(), r.lo.y()), r.hi, Vec2(r.lo.x(), r.hi.y())}});
      continue;
    }
    if (cutting.size() > 1 || loops[static_cast<std::size_t>(cutting[0])].hole)
      throw Error("the cell at " + point_text(r.centre()) + " is cut by " +
                  (cutting.size() > 1 ? std::string("two contours of the region")
                                      : std::string("the boundary of a hole")) +
                  ": give the cells a box that keeps clear of it, or a smaller size there");
    const double leaf_area = (r.hi - r.lo).prod();
    std::vector<Vec2> part = cleaned(clip_to(loops[static_cast<std::size_t>(cutting[0])].points, r, eps), eps);
    if (part.size() < 3 || signed_area(part) < 1e-9 * leaf_area) continue;  // the leaf only touches the region
    if (boundary_entries(part, r, eps) > 1)
      throw Error("the region's boundary enters the cell at " + point_text(r.centre()) +
                  " more than once (a slot or a tooth narrower than the cells): give a smaller size there");
    Cell cell{std::move(part)};
    if (cell.triangles().empty())
      throw Error("the cell at " + point_text(r.centre()) + " is not a simple polygon: give a smaller size there");
    polygons.push_back(std::move(cell));
  }
  // The leaves' cells, crossed ones through their neighbours' vertices.
  double smallest = std::numeric_limits<double>::infinity();
  for (const Rect& r : leaves) smallest = std::min(smallest, r.longer_side());
  const VertexBuckets vertices(options.crossed ? polygons : std::vector<Cell>{}, lo, smallest);
  std::vector<Cell> cells;
  for (auto& polygon : polygons) add_cell(cells, std::move(polygon), options.crossed, vertices, eps);
  if (cells.empty()) throw Error("no cell lies inside the region (is the box outside it?)");
  return cells;
}

std::array<double, 2> cell_size_range(const std::vector<Cell>& cells) {
  std::array<double, 2> range{0.0, std::numeric_limits<double>::infinity()};
  for (const auto& cell : cells) {
    const double h = std::sqrt(std::abs(cell.area()));
    range[0] = std::max(range[0], h), range[1] = std::min(range[1], h);
  }
  return range;
}

}  // namespace bemcontact::plasticity
