#include "shard.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace platon::app {

namespace {

uint64_t fnv1a(const std::string& text, uint64_t hash = 0xcbf29ce484222325ULL) {
  for (const unsigned char c : text) hash = (hash ^ c) * 0x100000001b3ULL;
  return hash;
}

// A whole number from the whole of `text`, or nothing.
std::optional<uint64_t> whole(const std::string& text) {
  uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

constexpr uint64_t kMostShards = 100'000;

// A shard from an index and a total as a convention writes them (`base` 0 or 1).
Shard shardOf(const std::string& indexText, const std::string& totalText, int base, const std::string& from,
              const std::string& what) {
  const std::optional<uint64_t> index = whole(indexText), total = whole(totalText);
  if (!total || *total < 1 || *total > kMostShards)
    throw std::runtime_error(what + ": the number of shards must be a whole number from 1 to 100000, got '" +
                             totalText + "'");
  if (!index || *index < static_cast<uint64_t>(base) || *index - base >= *total)
    throw std::runtime_error(what + ": the shard must be a whole number from " + std::to_string(base) + " to " +
                             std::to_string(*total - 1 + base) + ", got '" + indexText + "'");
  return {static_cast<uint32_t>(*index - base), static_cast<uint32_t>(*total), from};
}

}  // namespace

std::optional<Shard> askedShard(const std::string& flag, const std::string& totalFlag, const Environment& env) {
  std::vector<Shard> asked;
  auto pair = [&](const char* index, const char* total, int base, const char* from) {
    const char* i = env(index);
    const char* n = env(total);
    if (!i && (!n || std::string(n) == "1")) return;  // GitLab sets CI_NODE_TOTAL=1 for a job that is not parallel
    if (!i || !n)
      throw std::runtime_error(std::string(from) + ": " + (i ? total : index) + " is not set but " +
                               (i ? index : total) + " is");
    asked.push_back(shardOf(i, n, base, from, std::string(index) + "=" + i + ", " + total + "=" + n));
  };
  // The flag says what this run is for: it wins over whatever the environment holds (a run nested in
  // a sharded CI job that must run its own suite whole says --shard 1/1).
  if (!flag.empty()) {
    const size_t slash = flag.find('/');
    if (slash == std::string::npos)
      throw std::runtime_error("--shard " + flag + ": expected I/N, the I-th of N shards (1 <= I <= N)");
    return shardOf(flag.substr(0, slash), flag.substr(slash + 1), 1, "--shard", "--shard " + flag);
  }
  pair("TEST_SHARD_INDEX", "TEST_TOTAL_SHARDS", 0, "Bazel");
  pair("GTEST_SHARD_INDEX", "GTEST_TOTAL_SHARDS", 0, "GoogleTest");
  // GitLab sets CI_NODE_INDEX and CI_NODE_TOTAL for `parallel: N` and also for `parallel: matrix`,
  // whose jobs each run a whole suite of their own: only a job named "<name> I/N", as `parallel: N`
  // names them, is a shard.
  if (const char* job = env("CI_JOB_NAME");
      !job || !env("CI_NODE_INDEX") || !env("CI_NODE_TOTAL") ||
      std::string(job).ends_with(std::string(" ") + env("CI_NODE_INDEX") + "/" + env("CI_NODE_TOTAL")))
    pair("CI_NODE_INDEX", "CI_NODE_TOTAL", 1, "GitLab");
  if (!totalFlag.empty()) {
    const char* index = env("JOB_COMPLETION_INDEX");
    if (!index)
      throw std::runtime_error("--shards " + totalFlag +
                               ": the shard's index comes from JOB_COMPLETION_INDEX (a Kubernetes indexed job), "
                               "which is not set; use --shard I/N elsewhere");
    asked.push_back(shardOf(index, totalFlag, 0, "Kubernetes",
                            "JOB_COMPLETION_INDEX=" + std::string(index) + ", --shards " + totalFlag));
  }
  if (asked.empty()) return std::nullopt;
  for (const Shard& s : asked)
    if (s.index != asked[0].index || s.total != asked[0].total)
      throw std::runtime_error("two ways of asking for a shard disagree: " + asked[0].from + " asks for " +
                               std::to_string(asked[0].index + 1) + "/" + std::to_string(asked[0].total) + ", " +
                               s.from + " for " + std::to_string(s.index + 1) + "/" + std::to_string(s.total));
  return asked[0];
}

std::vector<uint32_t> splitIntoShards(const std::vector<std::string>& files, uint32_t total,
                                      const std::map<std::string, double>& durations) {
  std::vector<size_t> order(files.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::vector<uint64_t> hashes(files.size());
  for (size_t i = 0; i < files.size(); ++i) hashes[i] = fnv1a(files[i]);
  auto byHash = [&](size_t a, size_t b) {
    if (hashes[a] != hashes[b]) return hashes[a] < hashes[b];
    if (files[a] != files[b]) return files[a] < files[b];
    return a < b;
  };
  std::vector<uint32_t> shard(files.size(), 0);
  if (total <= 1) return shard;
  // A duration that is no time (NaN, infinite, negative: a report edited by hand) is not known.
  auto durationOf = [&](const std::string& f) -> std::optional<double> {
    const auto d = durations.find(f);
    if (d == durations.end() || !std::isfinite(d->second) || d->second < 0 || d->second > 1e9) return std::nullopt;
    return d->second;
  };
  std::vector<double> known;
  for (const std::string& f : files)
    if (const std::optional<double> d = durationOf(f)) known.push_back(*d);
  if (known.empty()) {
    std::sort(order.begin(), order.end(), byHash);
    for (size_t k = 0; k < order.size(); ++k) shard[order[k]] = static_cast<uint32_t>(k % total);
    return shard;
  }
  const double mean = std::accumulate(known.begin(), known.end(), 0.0) / static_cast<double>(known.size());
  std::vector<double> seconds(files.size());
  for (size_t i = 0; i < files.size(); ++i) seconds[i] = durationOf(files[i]).value_or(mean);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (seconds[a] != seconds[b]) return seconds[a] > seconds[b];
    return byHash(a, b);
  });
  std::vector<double> load(total, 0.0);
  for (const size_t i : order) {
    const auto least = std::min_element(load.begin(), load.end());
    shard[i] = static_cast<uint32_t>(least - load.begin());
    *least += seconds[i];
  }
  return shard;
}

std::string suiteIdentity(const std::vector<std::string>& files) {
  std::vector<std::string> sorted = files;
  std::sort(sorted.begin(), sorted.end());
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (const std::string& f : sorted) hash = fnv1a(f + '\n', hash);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return std::to_string(files.size()) + " " + hex;
}

}  // namespace platon::app
