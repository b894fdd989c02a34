#include "common/parallel_exceptions.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <stdexcept>
#include <string>

namespace molsurf {
namespace {

TEST(ParallelExceptions, NothingThrownRunsEveryIteration) {
  ParallelExceptions errors;
  std::atomic<int> ran{0};
#pragma omp parallel for num_threads(2)
  for (std::int64_t i = 0; i < 1000; ++i) errors.run(i, [&] { ++ran; });
  EXPECT_NO_THROW(errors.rethrow());
  EXPECT_EQ(ran.load(), 1000);
}

TEST(ParallelExceptions, AThrowLeavesTheRegionAsTheSameException) {
  for (int threads : {1, 2}) {
    ParallelExceptions errors;
#pragma omp parallel for num_threads(threads) schedule(static, 1)
    for (std::int64_t i = 0; i < 1000; ++i)
      errors.run(i, [&] {
        if (i == 500 || i == 700) throw std::runtime_error("iteration " + std::to_string(i));
      });
    try {
      errors.rethrow();
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_TRUE(what == "iteration 500" || what == "iteration 700") << what;
      if (threads == 1) EXPECT_EQ(what, "iteration 500");  // in order: the first one stops the rest
    }
  }
}

TEST(ParallelExceptions, AnAllocationFailureBecomesBadAlloc) {
  ParallelExceptions errors;
#pragma omp parallel for num_threads(2)
  for (std::int64_t i = 0; i < 4; ++i)
    errors.run(i, [&] {
      if (i == 3) throw std::bad_alloc();
    });
  EXPECT_THROW(errors.rethrow(), std::bad_alloc);
}

}  // namespace
}  // namespace molsurf
