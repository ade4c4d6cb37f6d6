// Built instead of hmatrix.cpp when hmat-oss is not found (BEMCONTACT_WITH_HMAT=OFF or
// no libhmat-oss-dev): every compressed operator is refused with the remedy.
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/hmatrix.hpp"

namespace bemcontact::operators {

bool hmatrix_available() { return false; }

struct HMatrix::Handle {};

HMatrix::HMatrix(const std::vector<Vec2>&, const std::vector<Vec2>&, const BlockFunction&, const HMatrixOptions&,
                 std::string what, const FractionCallback&) {
  throw InputError(SourceLocation{}, "the compressed operator (for " + what +
                                         ") needs hmat-oss: install libhmat-oss-dev and rebuild with "
                                         "-DBEMCONTACT_WITH_HMAT=ON, or use operator = \"dense\"");
}
HMatrix::~HMatrix() = default;
HMatrix::HMatrix(HMatrix&&) noexcept = default;
HMatrix& HMatrix::operator=(HMatrix&&) noexcept = default;
Matrix HMatrix::apply(const Matrix&) const { return {}; }
Matrix HMatrix::entries(const std::vector<Index>&, const std::vector<Index>&) const { return {}; }
void HMatrix::factorize(bool, const FractionCallback&) {}
void HMatrix::solve_in_place(Matrix&) const {}
void HMatrix::solve_transposed_in_place(Matrix&) const {}
std::size_t HMatrix::stored_values() const { return 0; }
double HMatrix::compression_ratio() const { return 0.0; }

}  // namespace bemcontact::operators
