// One shard of a suite of scenarios: which runner of several this process is, asked for with
// `platon run --shard I/N` or read from the conventions of the runners people already have, and
// which scenarios that runner runs. Every runner computes the same split by itself, from the paths
// (and, when given, the last run's durations): nothing is handed out at run time.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace platon::app {

struct Shard {
  uint32_t index = 0;  // 0-based
  uint32_t total = 1;
  std::string from;  // where it was asked for: "--shard", "Bazel", "GoogleTest", "GitLab", "Kubernetes"
};

// Reads an environment variable (std::getenv; tests pass their own).
using Environment = std::function<const char*(const char*)>;

// The shard asked for: `flag` ("I/N", 1 <= I <= N, as Playwright and Jest write it), which wins
// over the environment; else the runners' conventions, which must agree when several are set:
// Bazel (TEST_SHARD_INDEX, TEST_TOTAL_SHARDS, 0-based); GoogleTest (GTEST_SHARD_INDEX,
// GTEST_TOTAL_SHARDS, 0-based); GitLab's `parallel: N` jobs (CI_NODE_INDEX, CI_NODE_TOTAL,
// 1-based; not a `parallel: matrix` job, which GitLab gives the same variables); a Kubernetes
// indexed job (JOB_COMPLETION_INDEX, 0-based, with the total from `totalFlag`, since the job
// passes it itself). Nothing: the whole suite. Throws std::runtime_error naming the flag or
// variable for a value that is not a shard (I outside 1..N, N = 0, not a number), for a total
// without an index, and when two conventions ask for different shards.
std::optional<Shard> askedShard(const std::string& flag, const std::string& totalFlag, const Environment& env);

// The shard (0-based) each of `files` belongs to, out of `total`. Without durations the files,
// ordered by a 64-bit FNV-1a hash of their path (ties by path), are dealt to the shards in turn:
// counts differ by one at most. With durations (seconds by path, from a JUnit report of an earlier
// run), each file in turn, longest first, goes to the shard with the least time so far (a file
// with no duration counts as the mean of the known ones): the shards' times balance. Either way it
// depends on the paths and the durations only, so every runner computes the same split.
std::vector<uint32_t> splitIntoShards(const std::vector<std::string>& files, uint32_t total,
                                      const std::map<std::string, double>& durations);

// What identifies the suite that was split: its number of files and a hash of their paths in
// sorted order ("16 9f2c..."). Each shard's JUnit report carries it, so a merge can tell shards of
// different suites apart, and knows how many scenarios it must find.
std::string suiteIdentity(const std::vector<std::string>& files);

}  // namespace platon::app
