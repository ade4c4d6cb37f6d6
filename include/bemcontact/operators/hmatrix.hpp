#pragma once
// Hierarchical matrices on hmat-oss (Debian's libhmat-oss-dev): the rows and columns are
// clustered by the positions of their unknowns, far blocks are compressed by adaptive
// cross approximation (ACA+) to a relative accuracy, near blocks stay dense, and the LU
// factorisation runs on the compressed format (H-LU, truncated at the same accuracy).
// Memory and time grow as N log N instead of N^2 and N^3.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bemcontact/core/types.hpp"
#include "bemcontact/operators/progress.hpp"

namespace bemcontact::operators {

// False in a build without hmat-oss (BEMCONTACT_WITH_HMAT=OFF): "auto" then stays dense,
// and only an explicit "compressed" is refused (with the remedy).
bool hmatrix_available();

struct HMatrixOptions {
  double accuracy = 1e-10;  // relative accuracy of compressed blocks and of the H-LU
  double eta = 2.0;        // a block is compressed when min(diameters) <= eta * distance
  int leaf_size = 64;      // largest cluster kept whole
  // The component (0, 1, ...) of each row unknown, in the caller's numbering (empty: one).
  // With several, a compressed block is approximated one component's rows at a time
  // (hmat-oss's strata), and the parts summed and truncated. ACA+ on the interleaved
  // components of a tensor kernel (x and y of a node) stops far above the accuracy asked
  // where one component's part is small or vanishes (H on collinear nodes): blocks of the
  // 4 001-pair rigid cylinder's system at 7e-6 against the 1e-11 asked, and its pressures
  // 2.8e-4 of p0 off the dense operator's (3e-6 by component).
  std::vector<int> row_component;
  // Exact zeros the caller knows from the geometry (optional, with row_component; empty:
  // none): the straight line (an id >= 0, -1 none) each row's point and each column's support
  // lie on, and per column the components (bit k) of whose rows it is zero on its own line.
  // Then in a compressed block whose rows all lie on one line, those columns are not
  // computed. Without them, ACA+ by component looks through every column that is zero in its
  // rows for a nonzero one, computing each: on a straight boundary (plane kernels: H's xx and
  // yy, G's xy and yx vanish there) the whole block, where it could take hours and held 4.1 GB
  // (the rigid cylinder's [H' | G] at 32 001 pairs).
  std::vector<int> row_line, col_line;
  std::vector<unsigned char> col_null_components;

  static HMatrixOptions with_accuracy(double accuracy) {
    HMatrixOptions out;
    out.accuracy = accuracy;
    return out;
  }
};

// Entries of a block: out[r + c * rows.size()] = A(rows[r], cols[c]) (column-major), for
// rows and columns in the caller's numbering. Called from several threads at once.
using BlockFunction =
    std::function<void(const std::vector<Index>& rows, const std::vector<Index>& cols, double* out)>;

class HMatrix {
 public:
  // rows / cols: the position of each row / column unknown (several may share one).
  // `progress` hears the assembly's fraction after each block (thousands of calls, from
  // the assembling thread); an exception from it stops the assembly.
  HMatrix(const std::vector<Vec2>& row_points, const std::vector<Vec2>& col_points, const BlockFunction& entries,
          const HMatrixOptions& options, std::string what, const FractionCallback& progress = {});
  ~HMatrix();
  HMatrix(HMatrix&&) noexcept;
  HMatrix& operator=(HMatrix&&) noexcept;
  HMatrix(const HMatrix&) = delete;
  HMatrix& operator=(const HMatrix&) = delete;

  Index rows() const { return rows_; }
  Index cols() const { return cols_; }
  // y = A x (columns of x are separate vectors); before factorize() only.
  Matrix apply(const Matrix& x) const;
  // The entries A(rows[r], cols[c]) as the compressed blocks hold them (a rank-k block's in
  // k operations each); before factorize() only.
  Matrix entries(const std::vector<Index>& rows, const std::vector<Index>& cols) const;

  // H-LU in place (square only). keep_transposed also factors A^T, for
  // solve_transposed_in_place (twice the memory). Throws SolverError when a pivot
  // vanishes or the factors are not finite. `progress` hears the fraction after each
  // diagonal block (hmat-oss's progress hook), 1 at the end.
  void factorize(bool keep_transposed = false, const FractionCallback& progress = {});
  bool factorized() const { return factorized_; }
  void solve_in_place(Matrix& rhs) const;
  void solve_transposed_in_place(Matrix& rhs) const;

  // Values stored (compressed and dense leaves), against rows * cols uncompressed.
  std::size_t stored_values() const;
  double compression_ratio() const;

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
  std::unique_ptr<Handle> transposed_;
  Index rows_ = 0, cols_ = 0;
  bool factorized_ = false;
  std::string what_;
};

}  // namespace bemcontact::operators
