#pragma once
// A hierarchical matrix held as row pieces, assembled and applied on several threads at
// once. hmat-oss (Debian's) assembles one matrix on one thread, and its ACA+ asks for one
// row or column of a block at a time: about ten cells' kernels per call, too little work
// for a parallel loop inside the call. So the rows are split by position into
// kRowPieces pieces, each an HMatrix of its rows and all the columns, assembled and applied
// on its own thread. The split depends on the row points alone, so the entries and products
// do not depend on the thread count. For matrices that are only applied or read (an
// H-LU needs the whole square matrix: HMatrix).
#include <memory>
#include <string>
#include <vector>

#include "bemcontact/core/types.hpp"
#include "bemcontact/operators/hmatrix.hpp"

namespace bemcontact::operators {

class RowPartitionedHMatrix {
 public:
  // Four pieces: two threads share them within a piece's time of each other (the pieces'
  // costs differ where the points are graded), and each piece keeps the rows' clustering.
  static constexpr int kRowPieces = 4;
  // Fewer rows than this make one piece (a split would only cost compression).
  static constexpr Index kSmallestSplit = 1024;

  // As HMatrix; `progress` hears the pieces' mean fraction, from the calling thread only
  // (Python's callbacks may not run elsewhere); an exception from it stops every piece.
  RowPartitionedHMatrix(const std::vector<Vec2>& row_points, const std::vector<Vec2>& col_points,
                        const BlockFunction& entries, const HMatrixOptions& options, const std::string& what,
                        const FractionCallback& progress = {});
  ~RowPartitionedHMatrix();
  RowPartitionedHMatrix(RowPartitionedHMatrix&&) noexcept;
  RowPartitionedHMatrix& operator=(RowPartitionedHMatrix&&) noexcept;

  Index rows() const { return rows_; }
  Index cols() const { return cols_; }
  int pieces() const { return static_cast<int>(pieces_.size()); }
  // y = A x, the pieces' products on separate threads.
  Matrix apply(const Matrix& x) const;
  // The entries A(rows[r], cols[c]) as the pieces hold them.
  Matrix entries(const std::vector<Index>& rows, const std::vector<Index>& cols) const;
  std::size_t stored_values() const;
  double compression_ratio() const;

 private:
  struct Piece;
  std::vector<std::unique_ptr<Piece>> pieces_;
  std::vector<int> piece_of_;      // each row's piece
  std::vector<Index> local_row_;   // and its row there
  Index rows_ = 0, cols_ = 0;
};

// The pieces of a row split: row indices sorted along the longer side of their points'
// bounding box (ties by index), cut into `pieces` runs of nearly equal length, a cut moved
// forward past rows at the same point (a node's or cell's components stay together).
std::vector<std::vector<Index>> split_rows_by_position(const std::vector<Vec2>& points, int pieces);

}  // namespace bemcontact::operators
