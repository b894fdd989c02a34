#include "common/binned_median.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace molsurf {
namespace {

double nth_element_median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Each item holds `per_item` consecutive values of `values` (the last item fewer).
double median_by_items(const std::vector<double>& values, std::size_t per_item) {
  const auto items = static_cast<std::int64_t>((values.size() + per_item - 1) / per_item);
  return binned_median(items, [&](std::int64_t i, auto&& visit) {
    for (std::size_t k = static_cast<std::size_t>(i) * per_item; k < std::min(values.size(), (i + 1) * per_item); ++k)
      visit(values[k]);
  });
}

TEST(BinnedMedian, EqualsTheSelectedElement) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-5, 5);
  std::lognormal_distribution<double> skewed(0, 3);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 1 + random() % 100000;
    std::vector<double> v(n);
    for (double& x : v) {
      switch (trial % 4) {
        case 0: x = uniform(random); break;
        case 1: x = skewed(random); break;                       // most values in a few bins
        case 2: x = std::floor(uniform(random)); break;          // many equal values
        default: x = uniform(random) * std::ldexp(1.0, static_cast<int>(random() % 600) - 300);  // wide range
      }
    }
    SCOPED_TRACE(trial);
    const double expected = nth_element_median(v);
    for (const int threads : {1, 2, 3}) {
      omp_set_num_threads(threads);
      EXPECT_EQ(median_by_items(v, 1 + trial % 3), expected);
    }
  }
}

TEST(BinnedMedian, DegenerateSets) {
  EXPECT_TRUE(std::isnan(median_by_items({}, 1)));
  EXPECT_EQ(median_by_items({3.5}, 1), 3.5);
  EXPECT_EQ(median_by_items({2, 1}, 1), 2);          // rank 1 of 2: the upper of two
  EXPECT_EQ(median_by_items(std::vector<double>(50000, -1.25), 4), -1.25);
  // Items without values.
  const auto items = 100;
  const double m = binned_median(items, [](std::int64_t i, auto&& visit) {
    if (i % 10 == 0) visit(static_cast<double>(i));
  });
  EXPECT_EQ(m, 50);
}

}  // namespace
}  // namespace molsurf
