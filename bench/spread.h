// A figure measured several times on a shared machine (timings move by up to 30% between runs):
// its median and its spread, which the benchmarks quote together.
#pragma once
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace platon::bench {

struct Spread {
  double median = 0, low = 0, high = 0;

  static Spread of(std::vector<double> v) {
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return {n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2, v.front(), v.back()};
  }
  // "97,459 (96,746-145,229)"-style: `format` for each number, e.g. "%.0f".
  std::string show(const char* format = "%.0f") const {
    char m[64], lo[64], hi[64];
    std::snprintf(m, sizeof m, format, median);
    std::snprintf(lo, sizeof lo, format, low);
    std::snprintf(hi, sizeof hi, format, high);
    return std::string(m) + " (" + lo + "-" + hi + ")";
  }
};

// In how many runs `met(i)` held, as "k of n".
template <class Met>
std::string runsMet(size_t runs, Met met) {
  size_t k = 0;
  for (size_t i = 0; i < runs; ++i) k += met(i) ? 1 : 0;
  return std::to_string(k) + " of " + std::to_string(runs) + " runs";
}

}  // namespace platon::bench
