#pragma once
// The median of many values produced item by item (e.g. the edges of a mesh's faces),
// found in parallel without storing them all: counted in bins over their range, then only
// the values of the bin that holds the median are gathered and the median selected among
// them. A value's bin is a monotone function of it, so ranks carry over exactly: the
// result is the value std::nth_element gives at rank count / 2 (the lower median), for
// any thread count.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "common/parallel_threshold.hpp"

namespace molsurf {

// values_of(item, visit) calls visit(v) for each value of item (none, one or several);
// NaN for no value at all. Values must not be NaN.
template <class ValuesOf>
double binned_median(std::int64_t items, ValuesOf&& values_of) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::size_t count = 0;
#pragma omp parallel for schedule(static) reduction(min : lo) reduction(max : hi) reduction(+ : count) \
    if (items >= kParallelMinItems)
  for (std::int64_t i = 0; i < items; ++i)
    values_of(i, [&](double v) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      ++count;
    });
  if (count == 0) return std::numeric_limits<double>::quiet_NaN();
  constexpr std::size_t kBins = 4096;
  const double scale = hi > lo && std::isfinite(hi - lo) ? static_cast<double>(kBins - 1) / (hi - lo) : 0.0;
  auto bin = [&](double v) {
    const double x = (v - lo) * scale;  // rounding is monotone: so is the bin
    return x >= 0 ? std::min(kBins - 1, static_cast<std::size_t>(x)) : 0;
  };
  std::vector<std::size_t> histogram(kBins, 0);
#pragma omp parallel if (items >= kParallelMinItems)
  {
    std::vector<std::size_t> part(kBins, 0);
#pragma omp for schedule(static) nowait
    for (std::int64_t i = 0; i < items; ++i) values_of(i, [&](double v) { ++part[bin(v)]; });
#pragma omp critical(molsurf_binned_median)
    for (std::size_t k = 0; k < kBins; ++k) histogram[k] += part[k];
  }
  const std::size_t rank = count / 2;
  std::size_t median_bin = 0, below = 0;
  while (below + histogram[median_bin] <= rank) below += histogram[median_bin++];
  std::vector<double> in_bin;
#pragma omp parallel if (items >= kParallelMinItems)
  {
    std::vector<double> part;
#pragma omp for schedule(static) nowait
    for (std::int64_t i = 0; i < items; ++i)
      values_of(i, [&](double v) {
        if (bin(v) == median_bin) part.push_back(v);
      });
#pragma omp critical(molsurf_binned_median)
    in_bin.insert(in_bin.end(), part.begin(), part.end());
  }
  const auto nth = in_bin.begin() + static_cast<std::ptrdiff_t>(rank - below);
  std::nth_element(in_bin.begin(), nth, in_bin.end());
  return *nth;
}

}  // namespace molsurf
