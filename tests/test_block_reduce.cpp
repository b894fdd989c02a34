#include "common/block_reduce.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace molsurf {
namespace {

// Items folded and blocks combined in order: every index once, in increasing order, for
// sizes around the block's and the parallel threshold's, on 1 to 3 threads.
TEST(BlockReduce, EveryItemOnceInOrder) {
  for (const std::int64_t n : {0, 1, 4095, 4096, 4097, 20000, 3 * 4096 + 17})
    for (const int threads : {1, 2, 3}) {
      omp_set_num_threads(threads);
      const std::vector<std::int64_t> order = block_reduce(
          n, std::vector<std::int64_t>{}, [](std::vector<std::int64_t>& v, std::int64_t i) { v.push_back(i); },
          [](std::vector<std::int64_t>& total, const std::vector<std::int64_t>& block) {
            total.insert(total.end(), block.begin(), block.end());
          });
      ASSERT_EQ(order.size(), static_cast<std::size_t>(n)) << threads;
      for (std::int64_t i = 0; i < n; ++i) ASSERT_EQ(order[static_cast<std::size_t>(i)], i) << n << " " << threads;
    }
}

// A sum of values of very different sizes, where the order of additions shows in the last
// bits: the same bits on any number of threads.
TEST(BlockReduce, SumIsTheSameOnAnyThreadCount) {
  std::mt19937_64 random(11);
  std::vector<double> values(50000);
  for (double& x : values) x = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(random), static_cast<int>(random() % 60));
  auto sum = [&] {
    return block_reduce(
        static_cast<std::int64_t>(values.size()), 0.0, [&](double& s, std::int64_t i) { s += values[static_cast<std::size_t>(i)]; },
        [](double& total, double block) { total += block; });
  };
  omp_set_num_threads(1);
  const double one = sum();
  for (const int threads : {2, 3, 4}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(sum(), one) << threads;
  }
  double serial = 0;
  for (double x : values) serial += x;
  EXPECT_NEAR(one, serial, 1e-9 * std::ldexp(1.0, 60));
}

}  // namespace
}  // namespace molsurf
