// The decomposition spread over processes (dd/distribution.hpp), checked without MPI: two
// threads play two processes, summing through shared memory in a fixed order (so both
// hold the same bits, as MPI_Allreduce gives), each running the whole solve on the
// subdomains it owns. The answer must be the one-process answer.
#include <gtest/gtest.h>

#include <barrier>
#include <thread>

#include "bemcontact/dd/fibre_composite.hpp"
#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/dd/solver.hpp"

namespace bemcontact::dd {
namespace {

class ThreadTeam {
 public:
  explicit ThreadTeam(int size) : size_(size), slots_(static_cast<std::size_t>(size)), barrier_(size) {}

  Distribution member(int rank) {
    Distribution d;
    d.rank = rank;
    d.size = size_;
    d.sum_over_processes = [this, rank](double* data, std::size_t count) {
      slots_[static_cast<std::size_t>(rank)].assign(data, data + count);
      barrier_.arrive_and_wait();
      for (std::size_t i = 0; i < count; ++i) {
        double total = 0.0;
        for (const auto& slot : slots_) total += slot[i];
        data[i] = total;
      }
      barrier_.arrive_and_wait();
    };
    return d;
  }

 private:
  int size_;
  std::vector<std::vector<double>> slots_;
  std::barrier<> barrier_;
};

void expect_same_answer(const DecompositionProblem& problem) {
  const auto serial = solve_decomposition(problem);
  ASSERT_TRUE(serial.converged());
  ThreadTeam team(2);
  std::vector<DecompositionResult> results(2);
  std::vector<std::thread> threads;
  for (int rank = 0; rank < 2; ++rank)
    threads.emplace_back([&, rank] {
      ParallelRun run;
      run.distribution = team.member(rank);
      results[static_cast<std::size_t>(rank)] = solve_decomposition(problem, {}, run);
    });
  for (auto& t : threads) t.join();
  for (const auto& result : results) {
    ASSERT_TRUE(result.converged()) << result.gmres.message;
    EXPECT_EQ(result.processes, 2);
    EXPECT_EQ(result.gmres.iterations, serial.gmres.iterations);
    EXPECT_EQ(result.coarse_dimension, serial.coarse_dimension);
    EXPECT_EQ(result.floating_modes, serial.floating_modes);
    for (std::size_t s = 0; s < serial.subdomains.size(); ++s) {
      const auto& a = serial.subdomains[s].boundary;
      const auto& b = result.subdomains[s].boundary;
      ASSERT_EQ(a.displacement.size(), b.displacement.size());
      double u_scale = 0.0, p_scale = 0.0, du = 0.0, dp = 0.0;
      for (std::size_t i = 0; i < a.displacement.size(); ++i) {
        u_scale = std::max(u_scale, a.displacement[i].norm());
        p_scale = std::max(p_scale, a.traction[i].norm());
        du = std::max(du, (a.displacement[i] - b.displacement[i]).norm());
        dp = std::max(dp, (a.traction[i] - b.traction[i]).norm());
      }
      // The same iteration with sums in another order: rounding only, amplified by the
      // interface problem's conditioning.
      EXPECT_LT(du, 1e-9 * u_scale) << "subdomain " << s;
      EXPECT_LT(dp, 1e-9 * p_scale) << "subdomain " << s;
    }
  }
  // Both processes own some subdomains.
  EXPECT_NE(std::count(results[0].owner.begin(), results[0].owner.end(), 0), 0);
  EXPECT_NE(std::count(results[0].owner.begin(), results[0].owner.end(), 1), 0);
}

TEST(Distribution, TheLargestSubdomainsGoFirstToTheLeastLoaded) {
  EXPECT_EQ(assign_subdomains({1.0, 8.0, 2.0, 3.0, 3.0}, 2), (std::vector<int>{0, 0, 1, 1, 1}));
  EXPECT_EQ(assign_subdomains({1.0, 1.0}, 1), (std::vector<int>{0, 0}));
}

TEST(Distribution, TwoProcessesGiveTheOneProcessAnswerBalanced) {
  FibreCompositeSpec spec;
  spec.fibres_per_side = 2;
  expect_same_answer(fibre_composite(spec));
}

TEST(Distribution, TwoProcessesGiveTheOneProcessAnswerUnpreconditioned) {
  expect_same_answer(plate_strips({4, 6}));  // mixed method, no preconditioner
}

}  // namespace
}  // namespace bemcontact::dd
