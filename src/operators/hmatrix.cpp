#include "bemcontact/operators/hmatrix.hpp"

#include <hmat/hmat.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <mutex>
#include <numeric>
#include <unordered_map>
#include <stdexcept>
#include <string>
#include <vector>

#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::operators {

bool hmatrix_available() { return true; }

// A member of HMatrix::Handle (external linkage), so not in the anonymous namespace.
struct ClusterTree {
  hmat_cluster_tree_t* tree = nullptr;
  std::vector<double> coordinates;
  ~ClusterTree() {
    if (tree) hmat_delete_cluster_tree(tree);
  }
};

namespace {

// One interface for the program (hmat's init/finalize are global); its settings are
// global too, so they are set under a lock just before a cluster tree is built.
hmat_interface_t& hmat_interface() {
  static hmat_interface_t* instance = [] {
    // hmat-oss calls BLAS on small blocks from one thread: OpenBLAS's own threads only
    // spin there (a third of a 4 001-pair rigid cylinder's samples in sched_yield and the
    // scheduler; its model 7.0 s against 4.1 s with one BLAS thread), so BLAS runs on one
    // thread, as the command sets it at its start (benchmarks and tests did not).
    use_single_threaded_blas();
    auto* i = new hmat_interface_t;  // never finalized: other matrices may still live
    hmat_init_default_interface(i, HMAT_DOUBLE_PRECISION);
    if (i->init() != 0) throw Error("hmat-oss failed to initialise");
    return i;
  }();
  return *instance;
}
std::mutex& settings_mutex() {
  static std::mutex m;
  return m;
}

// No exception may cross hmat-oss: the first one is kept and rethrown after its call.
struct DeferredError {
  std::mutex mutex;
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  void keep_current() {
    std::lock_guard<std::mutex> lock(mutex);
    if (!error) error = std::current_exception();
    failed = true;
  }
  void rethrow() const {
    if (error) std::rethrow_exception(error);
  }
};

// The data of one assembly, shared by the prepare, compute and release callbacks.
struct AssemblyContext {
  const BlockFunction* entries = nullptr;
  // The rows' components (HMatrixOptions::row_component; null: one), their count (the
  // strata), and the row and column points (a node's unknowns share one).
  const std::vector<int>* row_component = nullptr;
  int row_components = 1;
  const HMatrixOptions* lines = nullptr;  // row_line, col_line, col_null_components (null: none)
  const std::vector<Vec2>* row_points = nullptr;
  const std::vector<Vec2>* col_points = nullptr;
  DeferredError error;
  // Progress: hmat-oss assembles leaf by leaf (release_block ends each one). A leaf's time
  // lies between a constant (small dense blocks near the diagonal) and its area (the
  // entries of a dense block; ACA+ computes far fewer): counting half per leaf and half
  // per area followed the elapsed time within 15 % on plane and axisymmetric bodies, where
  // either alone strayed by up to 18 % and 22 %. Both totals are exact before assembly.
  const FractionCallback* progress = nullptr;
  double leaves = 1.0, area = 1.0;
  std::atomic<std::uint64_t> leaves_done{0}, area_done{0};
};

// The unknowns of a block that share a point (the components of a node), as groups of
// block-local indices: group g is order[start[g] .. start[g + 1]).
struct PointGroups {
  std::vector<int> order, start, group_of;
  PointGroups() = default;
  PointGroups(const std::vector<Index>& unknowns, const std::vector<Vec2>& points) {
    const int n = static_cast<int>(unknowns.size());
    order.resize(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    const auto at = [&](int k) -> const Vec2& {
      return points[static_cast<std::size_t>(unknowns[static_cast<std::size_t>(k)])];
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const Vec2 &p = at(a), &q = at(b);
      return p.x() != q.x() ? p.x() < q.x() : p.y() != q.y() ? p.y() < q.y() : a < b;
    });
    group_of.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      if (k == 0 || at(order[static_cast<std::size_t>(k)]) != at(order[static_cast<std::size_t>(k - 1)]))
        start.push_back(k);
      group_of[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = static_cast<int>(start.size()) - 1;
    }
    start.push_back(n);
  }
  std::vector<int> members(int local) const {
    const auto g = static_cast<std::size_t>(group_of[static_cast<std::size_t>(local)]);
    return {order.begin() + start[g], order.begin() + start[g + 1]};
  }
};

struct BlockData {
  AssemblyContext* context = nullptr;
  std::vector<Index> rows, cols;  // caller's numbering of the block's rows and columns
  // With strata: the point groups, and the whole rows and columns computed so far. Each
  // stratum's ACA+ asks for its own rows and columns, but a node's kernel block gives all
  // its components at once: they are kept for the strata to come.
  PointGroups row_groups, col_groups;
  std::unordered_map<int, std::vector<double>> row_cache, col_cache;
  std::vector<double> scratch;  // a line computed alone, once a cache is full
  int line = -1;                // the line all the block's rows lie on (HMatrixOptions::row_line)
};

// Lines kept per side of a block. ACA+ asks for one per rank of each stratum, but where a
// stratum's part of the block is exactly zero or of exact low rank it looks for a nonzero
// reference column through every free column (hmat-oss, findCol): kept, those were the whole
// block (4.1 GB in one block of the rigid cylinder's [H' | G] at 32 001 pairs).
constexpr std::size_t kMaxCachedLines = 256;

int row_component_of(const BlockData& block, int row) {
  const auto* labels = block.context->row_component;
  return labels ? (*labels)[static_cast<std::size_t>(block.rows[static_cast<std::size_t>(row)])] : 0;
}
// Stratum s holds the rows of component s.
char null_row_in_stratum(const hmat_block_info_t* info, int row, int stratum) {
  return row_component_of(*static_cast<const BlockData*>(info->user_data), row) != stratum ? 1 : 0;
}

// Column `col` of a block whose rows lie on one line, zero in the rows of `stratum`.
char null_column_in_stratum(const hmat_block_info_t* info, int col, int stratum) {
  const auto& block = *static_cast<const BlockData*>(info->user_data);
  if (stratum < 0) return 0;
  const auto& lines = *block.context->lines;
  const auto c = static_cast<std::size_t>(block.cols[static_cast<std::size_t>(col)]);
  return lines.col_line[c] == block.line && ((lines.col_null_components[c] >> stratum) & 1) != 0 ? 1 : 0;
}

void release_block(void* data) {
  auto* block = static_cast<BlockData*>(data);
  AssemblyContext& context = *block->context;
  if (context.progress && !context.error.failed) {
    const double leaves = static_cast<double>(++context.leaves_done);
    const double area = static_cast<double>(context.area_done += block->rows.size() * block->cols.size());
    try {
      (*context.progress)(std::min(1.0, 0.5 * leaves / context.leaves + 0.5 * area / context.area));
    } catch (...) {
      context.error.keep_current();
    }
  }
  delete block;
}

void prepare_block(int row_start, int row_count, int col_start, int col_count, int* row_hmat2client,
                   int* /*row_client2hmat*/, int* col_hmat2client, int* /*col_client2hmat*/, void* context,
                   hmat_block_info_t* info) {
  auto* data = new BlockData;
  data->context = static_cast<AssemblyContext*>(context);
  data->rows.resize(row_count);
  data->cols.resize(col_count);
  for (int r = 0; r < row_count; ++r) data->rows[r] = row_hmat2client[row_start + r];
  for (int c = 0; c < col_count; ++c) data->cols[c] = col_hmat2client[col_start + c];
  info->user_data = data;
  info->release_user_data = release_block;
  info->block_type = hmat_block_full;
  const AssemblyContext& assembly = *data->context;
  if (assembly.row_components > 1) {
    info->number_of_strata = assembly.row_components;
    info->is_guaranteed_null_row = null_row_in_stratum;
    if (assembly.lines && !data->rows.empty()) {
      const auto& row_line = assembly.lines->row_line;
      data->line = row_line[static_cast<std::size_t>(data->rows.front())];
      for (const Index r : data->rows)
        if (row_line[static_cast<std::size_t>(r)] != data->line) data->line = -1;
      if (data->line >= 0) info->is_guaranteed_null_col = null_column_in_stratum;
    }
  }
}

// The whole row (along_rows) or column k of a block, with those of the other unknowns at its
// point, computed once and kept (up to kMaxCachedLines; then the line alone, not kept).
const std::vector<double>& whole_line(BlockData& data, bool along_rows, int k) {
  auto& cache = along_rows ? data.row_cache : data.col_cache;
  if (const auto found = cache.find(k); found != cache.end()) return found->second;
  if (cache.size() >= kMaxCachedLines) {
    const std::vector<Index> line{(along_rows ? data.rows : data.cols)[static_cast<std::size_t>(k)]};
    const std::vector<Index>& across = along_rows ? data.cols : data.rows;
    data.scratch.resize(across.size());
    if (along_rows)
      (*data.context->entries)(line, across, data.scratch.data());
    else
      (*data.context->entries)(across, line, data.scratch.data());
    return data.scratch;
  }
  PointGroups& groups = along_rows ? data.row_groups : data.col_groups;
  if (groups.order.empty())  // made at the first request (dense leaves never ask)
    groups = PointGroups(along_rows ? data.rows : data.cols,
                         along_rows ? *data.context->row_points : *data.context->col_points);
  const std::vector<int> mates = groups.members(k);
  std::vector<Index> lines(mates.size());
  for (std::size_t i = 0; i < mates.size(); ++i)
    lines[i] = (along_rows ? data.rows : data.cols)[static_cast<std::size_t>(mates[i])];
  const std::vector<Index>& across = along_rows ? data.cols : data.rows;
  const std::size_t m = mates.size(), n = across.size();
  std::vector<double> values(m * n);
  if (along_rows)
    (*data.context->entries)(lines, across, values.data());  // m x n, column-major
  else
    (*data.context->entries)(across, lines, values.data());  // n x m
  for (std::size_t i = 0; i < m; ++i) {
    std::vector<double> line(n);
    for (std::size_t j = 0; j < n; ++j) line[j] = along_rows ? values[i + j * m] : values[j + i * n];
    cache[mates[i]] = std::move(line);
  }
  return cache[k];
}

// The entries of rows x cols of a block (hmat-oss's numbering within it) in one stratum (the
// rows of one component; -1: all), zero in the other rows.
void compute_block(hmat_block_compute_context_t* request) {
  auto* data = static_cast<BlockData*>(request->user_data);
  double* out = static_cast<double*>(request->block);
  const int row_count = request->row_count, col_count = request->col_count, stratum = request->stratum;
  std::fill(out, out + static_cast<std::size_t>(row_count) * col_count, 0.0);
  // After a failure the remaining blocks stay zeros, so that the assembly ends fast.
  if (data->context->error.failed) return;
  const auto in_stratum = [&](int r) { return stratum < 0 || row_component_of(*data, r) == stratum; };
  try {
    if (stratum >= 0 && row_count == 1 && col_count == static_cast<int>(data->cols.size())) {  // ACA+'s row
      if (!in_stratum(request->row_start)) return;
      const std::vector<double>& line = whole_line(*data, true, request->row_start);
      std::copy(line.begin(), line.end(), out);
      return;
    }
    if (stratum >= 0 && col_count == 1 && row_count == static_cast<int>(data->rows.size())) {  // ACA+'s column
      const std::vector<double>& line = whole_line(*data, false, request->col_start);
      for (int r = 0; r < row_count; ++r)
        if (in_stratum(r)) out[r] = line[static_cast<std::size_t>(r)];
      return;
    }
    std::vector<int> row_at;  // the request's rows in the stratum
    for (int r = 0; r < row_count; ++r)
      if (in_stratum(request->row_start + r)) row_at.push_back(r);
    if (row_at.empty()) return;
    std::vector<Index> rows(row_at.size()), cols(static_cast<std::size_t>(col_count));
    for (std::size_t r = 0; r < row_at.size(); ++r)
      rows[r] = data->rows[static_cast<std::size_t>(request->row_start + row_at[r])];
    for (int c = 0; c < col_count; ++c) cols[static_cast<std::size_t>(c)] = data->cols[static_cast<std::size_t>(request->col_start + c)];
    if (row_at.size() == static_cast<std::size_t>(row_count)) {
      (*data->context->entries)(rows, cols, out);
      return;
    }
    std::vector<double> part(rows.size() * cols.size());
    (*data->context->entries)(rows, cols, part.data());
    for (std::size_t c = 0; c < cols.size(); ++c)
      for (std::size_t r = 0; r < rows.size(); ++r)
        out[static_cast<std::size_t>(row_at[r]) + c * static_cast<std::size_t>(row_count)] = part[r + c * rows.size()];
  } catch (...) {
    data->context->error.keep_current();
    std::fill(out, out + static_cast<std::size_t>(row_count) * col_count, 0.0);
  }
}

void build_tree(ClusterTree& out, const std::vector<Vec2>& points) {
  out.coordinates.resize(2 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.coordinates[2 * i] = points[i].x();
    out.coordinates[2 * i + 1] = points[i].y();
  }
  hmat_clustering_algorithm_t* median = hmat_create_clustering_median();
  out.tree = hmat_create_cluster_tree(out.coordinates.data(), 2, static_cast<int>(points.size()), median);
  hmat_delete_clustering(median);
  if (!out.tree) throw Error("hmat-oss could not cluster the unknowns");
}

// hmat-oss's H-LU reports the rows factored so far, after each diagonal leaf. Its
// recursive LU also spends about a third of each level's time on the update between the
// two halves (measured 0.33-0.41 at the top level on plane and axisymmetric bodies of 8k-20k
// unknowns), where the rows stand still; the rows' fraction x is mapped to the time's
// with that share: with it the reports fell within 9 % of the elapsed time, against 25 %
// for x itself. The top level's update still shows as one step (from 33 % to 67 %).
double lu_time_fraction(double x) {
  constexpr double update = 1.0 / 3.0, half = (1.0 - update) / 2.0;
  double done = 0.0, scale = 1.0;
  for (int level = 0; level < 40; ++level) {
    if (x <= 0.5) {
      x *= 2.0;
    } else {
      done += scale * (half + update);
      x = 2.0 * x - 1.0;
    }
    scale *= half;
  }
  return std::clamp(done + scale * x, 0.0, 1.0);
}

struct LuProgress {
  const FractionCallback* progress;
  double offset, share;
  DeferredError* error;
};

void report_lu_progress(hmat_progress_t* bar) {
  auto* state = static_cast<LuProgress*>(bar->user_data);
  if (state->error->failed || bar->max <= 0) return;
  try {
    const double rows = static_cast<double>(bar->current) / static_cast<double>(bar->max);
    (*state->progress)(state->offset + state->share * lu_time_fraction(std::min(1.0, rows)));
  } catch (...) {
    state->error->keep_current();
  }
}

}  // namespace

struct HMatrix::Handle {
  ClusterTree row_tree, col_tree;
  hmat_matrix_t* matrix = nullptr;
  ~Handle() {
    if (matrix) hmat_interface().destroy(matrix);
  }
};

HMatrix::HMatrix(const std::vector<Vec2>& row_points, const std::vector<Vec2>& col_points,
                 const BlockFunction& entries, const HMatrixOptions& options, std::string what,
                 const FractionCallback& progress)
    : handle_(std::make_unique<Handle>()),
      rows_(static_cast<Index>(row_points.size())),
      cols_(static_cast<Index>(col_points.size())),
      what_(std::move(what)) {
  if (rows_ == 0 || cols_ == 0) throw Error("HMatrix: empty matrix");
  if (!(options.accuracy > 0.0 && options.accuracy < 1.0)) throw Error("HMatrix: accuracy must lie in (0, 1)");
  hmat_interface_t& hi = hmat_interface();
  {
    std::lock_guard<std::mutex> lock(settings_mutex());
    hmat_settings_t settings;
    hmat_get_parameters(&settings);
    settings.maxLeafSize = options.leaf_size;
    settings.compressionMinLeafSize = options.leaf_size;
    settings.coarsening = 0;
    hmat_set_parameters(&settings);
    build_tree(handle_->row_tree, row_points);
    build_tree(handle_->col_tree, col_points);
  }
  hmat_admissibility_param_t admissibility_param;
  hmat_init_admissibility_param(&admissibility_param);
  admissibility_param.eta = options.eta;
  hmat_admissibility_t* admissibility = hmat_create_admissibility(&admissibility_param);
  handle_->matrix = hi.create_empty_hmatrix_admissibility(handle_->row_tree.tree, handle_->col_tree.tree, 0, admissibility);
  hmat_delete_admissibility(admissibility);
  if (!handle_->matrix) throw Error("hmat-oss could not build the block structure of " + what_);
  hi.set_low_rank_epsilon(handle_->matrix, options.accuracy);

  AssemblyContext context;
  context.entries = &entries;
  if (!options.row_component.empty()) {
    if (static_cast<Index>(options.row_component.size()) != rows_) throw std::logic_error("HMatrix: a component per row");
    if (*std::min_element(options.row_component.begin(), options.row_component.end()) < 0)
      throw std::logic_error("HMatrix: a negative component");
    context.row_component = &options.row_component;
    context.row_components = *std::max_element(options.row_component.begin(), options.row_component.end()) + 1;
  }
  if (!options.row_line.empty() || !options.col_line.empty() || !options.col_null_components.empty()) {
    if (static_cast<Index>(options.row_line.size()) != rows_ || static_cast<Index>(options.col_line.size()) != cols_ ||
        static_cast<Index>(options.col_null_components.size()) != cols_ || options.row_component.empty())
      throw std::logic_error("HMatrix: a line per row and column, a null mask per column, and the rows' components");
    context.lines = &options;
  }
  context.row_points = &row_points;
  context.col_points = &col_points;
  if (progress) {
    hmat_info_t structure;  // of the empty matrix: its leaves
    hi.get_info(handle_->matrix, &structure);
    context.progress = &progress;
    context.leaves = std::max(1.0, static_cast<double>(structure.full_count + structure.rk_count));
    context.area = static_cast<double>(rows_) * static_cast<double>(cols_);
    progress(0.0);
  }
  hmat_assemble_context_t assemble;
  hmat_assemble_context_init(&assemble);
  assemble.user_context = &context;
  assemble.prepare = prepare_block;
  assemble.advanced_compute = compute_block;
  assemble.compression = hmat_create_compression_aca_plus(options.accuracy);
  assemble.lower_symmetric = 0;
  assemble.factorization = hmat_factorization_none;
  assemble.progress = nullptr;
  const int status = hi.assemble_generic(handle_->matrix, &assemble);
  hmat_delete_compression(assemble.compression);
  context.error.rethrow();
  if (status != 0) throw SolverError("hmat-oss failed to assemble " + what_);
  if (progress) progress(1.0);
}

HMatrix::~HMatrix() = default;
HMatrix::HMatrix(HMatrix&&) noexcept = default;
HMatrix& HMatrix::operator=(HMatrix&&) noexcept = default;

Matrix HMatrix::apply(const Matrix& x) const {
  if (factorized_) throw Error("HMatrix: apply after factorisation");
  if (x.rows() != cols_) throw Error("HMatrix: vector of the wrong size");
  Matrix in = x;  // hmat reorders its input in place and back
  Matrix out = Matrix::Zero(rows_, x.cols());
  double one = 1.0, zero = 0.0;
  if (hmat_interface().gemv('N', &one, handle_->matrix, in.data(), &zero, out.data(), static_cast<int>(x.cols())) != 0)
    throw SolverError("hmat-oss failed to multiply " + what_);
  return out;
}

Matrix HMatrix::entries(const std::vector<Index>& rows, const std::vector<Index>& cols) const {
  if (factorized_) throw Error("HMatrix: entries after factorisation");
  Matrix out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  if (rows.empty() || cols.empty()) return out;
  // hmat-oss numbers the query from 1 (its "natural" numbering: the caller's plus one).
  std::vector<int> row_query(rows.size()), col_query(cols.size());
  for (std::size_t r = 0; r < rows.size(); ++r) row_query[r] = static_cast<int>(rows[r]) + 1;
  for (std::size_t c = 0; c < cols.size(); ++c) col_query[c] = static_cast<int>(cols[c]) + 1;
  hmat_get_values_context_t context{};
  context.matrix = handle_->matrix;
  context.values = out.data();
  context.row_size = static_cast<int>(rows.size());
  context.col_size = static_cast<int>(cols.size());
  context.row_indices = row_query.data();
  context.col_indices = col_query.data();
  if (hmat_interface().get_values(&context) != 0) throw SolverError("hmat-oss failed to read entries of " + what_);
  return out;
}

void HMatrix::factorize(bool keep_transposed, const FractionCallback& progress) {
  if (rows_ != cols_) throw Error("HMatrix: factorisation of a rectangular matrix");
  hmat_interface_t& hi = hmat_interface();
  if (progress) progress(0.0);
  // With keep_transposed, A then A^T: each half of the progress.
  const double share = keep_transposed ? 0.5 : 1.0;
  DeferredError progress_error;  // rethrown as it is, not as a failed factorisation
  auto factor = [&](hmat_matrix_t* m, double offset) {
    LuProgress state{&progress, offset, share, &progress_error};
    hmat_progress_t bar{};
    bar.user_data = &state;
    bar.update = report_lu_progress;
    hmat_factorization_context_t context;
    hmat_factorization_context_init(&context);
    context.factorization = hmat_factorization_lu;
    context.progress = progress ? &bar : nullptr;
    const int status = hi.factorize_generic(m, &context);
    if (progress_error.failed) return;
    if (status != 0) throw SolverError("hmat-oss failed to factor " + what_);
  };
  if (keep_transposed) {
    transposed_ = std::make_unique<Handle>();
    transposed_->matrix = hi.copy(handle_->matrix);
    if (!transposed_->matrix || hi.transpose(transposed_->matrix) != 0)
      throw SolverError("hmat-oss failed to transpose " + what_);
  }
  try {
    factor(handle_->matrix, 0.0);
    if (transposed_ && !progress_error.failed) factor(transposed_->matrix, 0.5);
  } catch (const std::exception& e) {
    throw SolverError(std::string(e.what()).find("hmat") != std::string::npos
                          ? std::string(e.what())
                          : "the hierarchical LU of " + what_ + " failed: " + e.what());
  }
  progress_error.rethrow();
  factorized_ = true;
  if (progress) progress(1.0);
}

namespace {

// Solves with one set of hierarchical LU factors; `which` names the matrix in messages.
void solve_with_factors(hmat_matrix_t* factors, Matrix& rhs, Index rows, const std::string& which) {
  if (rhs.rows() != rows) throw Error("HMatrix: right-hand side of the wrong size");
  if (hmat_interface().solve_systems(factors, rhs.data(), static_cast<int>(rhs.cols())) != 0)
    throw SolverError("hmat-oss failed to solve with " + which);
  if (!rhs.allFinite())
    throw SolverError(which + " is singular: its hierarchical LU gave a non-finite solution");
}

}  // namespace

void HMatrix::solve_in_place(Matrix& rhs) const {
  if (!factorized_) throw Error("HMatrix: solve before factorisation");
  solve_with_factors(handle_->matrix, rhs, rows_, what_);
}

void HMatrix::solve_transposed_in_place(Matrix& rhs) const {
  if (!transposed_) throw Error("HMatrix: no transposed factors (factorize(true))");
  solve_with_factors(transposed_->matrix, rhs, rows_, "the transpose of " + what_);
}

std::size_t HMatrix::stored_values() const {
  hmat_info_t info;
  hmat_interface().get_info(handle_->matrix, &info);
  std::size_t total = info.compressed_size;
  if (transposed_) {
    hmat_interface().get_info(transposed_->matrix, &info);
    total += info.compressed_size;
  }
  return total;
}

double HMatrix::compression_ratio() const {
  return static_cast<double>(stored_values()) / (static_cast<double>(rows_) * static_cast<double>(cols_));
}

}  // namespace bemcontact::operators
