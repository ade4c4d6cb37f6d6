#include "bemcontact/operators/row_partitioned_hmatrix.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <numeric>
#include <stdexcept>

#include <omp.h>

#include "bemcontact/core/error.hpp"

namespace bemcontact::operators {

struct RowPartitionedHMatrix::Piece {
  std::vector<Index> rows;  // the whole matrix's rows, in the piece's order
  HMatrix matrix;
};

std::vector<std::vector<Index>> split_rows_by_position(const std::vector<Vec2>& points, int pieces) {
  const auto n = static_cast<Index>(points.size());
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index{0});
  if (n == 0 || pieces <= 1) return {order};
  Vec2 low = points.front(), high = points.front();
  for (const Vec2& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  const int axis = (high - low).x() >= (high - low).y() ? 0 : 1;
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    return points[static_cast<std::size_t>(a)][axis] < points[static_cast<std::size_t>(b)][axis];
  });
  std::vector<std::vector<Index>> out;
  Index start = 0;
  for (int p = 1; p <= pieces && start < n; ++p) {
    Index end = p == pieces ? n : std::max(start + 1, (n * p) / pieces);
    while (end < n && points[static_cast<std::size_t>(order[end])] == points[static_cast<std::size_t>(order[end - 1])])
      ++end;
    out.emplace_back(order.begin() + start, order.begin() + end);
    start = end;
  }
  return out;
}

RowPartitionedHMatrix::RowPartitionedHMatrix(const std::vector<Vec2>& row_points,
                                             const std::vector<Vec2>& col_points, const BlockFunction& entries,
                                             const HMatrixOptions& options, const std::string& what,
                                             const FractionCallback& progress)
    : rows_(static_cast<Index>(row_points.size())), cols_(static_cast<Index>(col_points.size())) {
  if (!options.row_component.empty() && static_cast<Index>(options.row_component.size()) != rows_)
    throw std::logic_error("RowPartitionedHMatrix: a component per row");
  const auto split = split_rows_by_position(row_points, rows_ < kSmallestSplit ? 1 : kRowPieces);
  const auto count = static_cast<int>(split.size());
  piece_of_.assign(static_cast<std::size_t>(rows_), 0);
  local_row_.assign(static_cast<std::size_t>(rows_), 0);
  for (int p = 0; p < count; ++p)
    for (std::size_t r = 0; r < split[p].size(); ++r) {
      piece_of_[static_cast<std::size_t>(split[p][r])] = p;
      local_row_[static_cast<std::size_t>(split[p][r])] = static_cast<Index>(r);
    }
  pieces_.resize(static_cast<std::size_t>(count));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
  std::atomic<bool> stop{false};
  // Each piece's fraction (of its rows); the calling thread reports their weighted mean.
  std::vector<std::atomic<double>> done(static_cast<std::size_t>(count));
  for (auto& fraction : done) fraction = 0.0;
  struct Stopped {};
  if (progress) progress(0.0);
// Not parallel for one piece: the entries' own parallel loops then keep both threads.
#pragma omp parallel for schedule(dynamic, 1) if (count > 1)
  for (int p = 0; p < count; ++p) {
    const bool caller = omp_get_thread_num() == 0;
    try {
      if (stop) throw Stopped{};
      const auto& rows = split[static_cast<std::size_t>(p)];
      std::vector<Vec2> points;
      points.reserve(rows.size());
      for (const Index r : rows) points.push_back(row_points[static_cast<std::size_t>(r)]);
      // The piece's row r is the matrix's rows[r].
      const BlockFunction piece_entries = [&entries, &rows](const std::vector<Index>& local, const std::vector<Index>& cols,
                                                            double* out) {
        std::vector<Index> global(local.size());
        for (std::size_t r = 0; r < local.size(); ++r) global[r] = rows[static_cast<std::size_t>(local[r])];
        entries(global, cols, out);
      };
      FractionCallback report;
      if (progress)
        report = [&, p, caller](double fraction) {
          if (stop) throw Stopped{};
          done[static_cast<std::size_t>(p)] = fraction;
          if (!caller) return;
          double mean = 0.0;
          for (int q = 0; q < count; ++q)
            mean += done[static_cast<std::size_t>(q)] * static_cast<double>(split[static_cast<std::size_t>(q)].size());
          progress(mean / static_cast<double>(rows_));
        };
      HMatrixOptions piece_options = options;  // the piece's rows' components and lines
      const auto piece_rows = [&rows](const std::vector<int>& per_row) {
        std::vector<int> out;
        if (!per_row.empty())
          for (const Index r : rows) out.push_back(per_row.at(static_cast<std::size_t>(r)));
        return out;
      };
      piece_options.row_component = piece_rows(options.row_component);
      piece_options.row_line = piece_rows(options.row_line);
      const std::string piece_name = count == 1 ? what : what + " (rows " + std::to_string(p + 1) + " of " + std::to_string(count) + ")";
      pieces_[static_cast<std::size_t>(p)] =
          std::make_unique<Piece>(Piece{rows, HMatrix(points, col_points, piece_entries, piece_options, piece_name, report)});
    } catch (const Stopped&) {
    } catch (...) {
      errors[static_cast<std::size_t>(p)] = std::current_exception();
      stop = true;
    }
  }
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  if (progress) progress(1.0);
}

RowPartitionedHMatrix::~RowPartitionedHMatrix() = default;
RowPartitionedHMatrix::RowPartitionedHMatrix(RowPartitionedHMatrix&&) noexcept = default;
RowPartitionedHMatrix& RowPartitionedHMatrix::operator=(RowPartitionedHMatrix&&) noexcept = default;

Matrix RowPartitionedHMatrix::apply(const Matrix& x) const {
  if (x.rows() != cols_) throw Error("RowPartitionedHMatrix: vector of the wrong size");
  Matrix y(rows_, x.cols());
  const auto count = static_cast<int>(pieces_.size());
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
#pragma omp parallel for schedule(dynamic, 1) if (count > 1)
  for (int p = 0; p < count; ++p) {
    try {
      const Piece& piece = *pieces_[static_cast<std::size_t>(p)];
      const Matrix part = piece.matrix.apply(x);
      for (std::size_t r = 0; r < piece.rows.size(); ++r) y.row(piece.rows[r]) = part.row(static_cast<Index>(r));
    } catch (...) {
      errors[static_cast<std::size_t>(p)] = std::current_exception();
    }
  }
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  return y;
}

Matrix RowPartitionedHMatrix::entries(const std::vector<Index>& rows, const std::vector<Index>& cols) const {
  Matrix out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  std::vector<std::vector<Index>> local(pieces_.size()), position(pieces_.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r] < 0 || rows[r] >= rows_) throw Error("RowPartitionedHMatrix: row out of range");
    const auto p = static_cast<std::size_t>(piece_of_[static_cast<std::size_t>(rows[r])]);
    local[p].push_back(local_row_[static_cast<std::size_t>(rows[r])]);
    position[p].push_back(static_cast<Index>(r));
  }
  for (std::size_t p = 0; p < pieces_.size(); ++p) {
    if (local[p].empty()) continue;
    const Matrix part = pieces_[p]->matrix.entries(local[p], cols);
    for (std::size_t r = 0; r < local[p].size(); ++r) out.row(position[p][r]) = part.row(static_cast<Index>(r));
  }
  return out;
}

std::size_t RowPartitionedHMatrix::stored_values() const {
  std::size_t total = 0;
  for (const auto& piece : pieces_) total += piece->matrix.stored_values();
  return total;
}

double RowPartitionedHMatrix::compression_ratio() const {
  return static_cast<double>(stored_values()) / (static_cast<double>(rows_) * static_cast<double>(cols_));
}

}  // namespace bemcontact::operators
