// The split of a suite into shards (apps/platon/shard.cpp): over random suites, totals and
// durations, every scenario falls in exactly one shard, the same one whatever order the files come
// in; and every runner's way of asking for a shard means the same shard.
#include "shard.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include <gtest/gtest.h>

#include "platon/testing/rng.h"

namespace platon::app {
namespace {

using platon::testing::Rng;

std::vector<std::string> randomSuite(Rng& rng, int n) {
  std::vector<std::string> files;
  for (int i = 0; i < n; ++i)
    files.push_back("tests/scenarios/s" + std::to_string(rng.next() % 100000) + "_" + std::to_string(i) + ".lua");
  return files;
}

TEST(Shards, EveryScenarioFallsInExactlyOneShardWhateverTheOrder) {
  Rng rng{11};
  for (int trial = 0; trial < 400; ++trial) {
    const int n = rng.between(0, 120);
    const auto total = static_cast<uint32_t>(rng.between(1, 9));
    std::vector<std::string> files = randomSuite(rng, n);
    std::map<std::string, double> durations;
    const bool timed = trial % 2 == 1;
    if (timed)
      for (const std::string& f : files)
        if (rng.between(0, 4) != 0) durations[f] = rng.uniform(0.001, 30.0);  // some scenarios are new: no time
    // A report edited by hand: times that are no times count as unknown.
    if (timed && !files.empty() && trial % 4 == 1) durations[files[0]] = trial % 8 == 1 ? -1.0 : std::nan("");
    auto valid = [&](const std::string& f) { return durations.count(f) && durations[f] >= 0; };  // NaN >= 0 is false
    const std::vector<uint32_t> shard = splitIntoShards(files, total, durations);
    ASSERT_EQ(shard.size(), files.size());
    std::vector<size_t> count(total, 0);
    std::vector<double> load(total, 0);
    double known = 0, most = 0;
    int knownCount = 0;
    for (const std::string& f : files)
      if (valid(f)) known += durations[f], ++knownCount;
    const double mean = knownCount == 0 ? 0 : known / knownCount;
    for (size_t i = 0; i < files.size(); ++i) {
      ASSERT_LT(shard[i], total);
      ++count[shard[i]];
      const double d = valid(files[i]) ? durations[files[i]] : mean;
      load[shard[i]] += d;
      most = std::max(most, d);
    }
    if (!timed) {  // dealt in turn: counts differ by one at most
      const auto [low, high] = std::minmax_element(count.begin(), count.end());
      EXPECT_LE(*high - *low, 1u) << "trial " << trial;
    } else {  // longest first to the least loaded: no shard is more than one scenario over the mean
      const double average = std::accumulate(load.begin(), load.end(), 0.0) / total;
      EXPECT_LE(*std::max_element(load.begin(), load.end()), average + most + 1e-9) << "trial " << trial;
    }
    // The same split for the same files in another order: each runner may glob in its own order.
    std::vector<size_t> order(files.size());
    std::iota(order.begin(), order.end(), size_t{0});
    for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.next() % i]);
    std::vector<std::string> shuffled;
    for (const size_t i : order) shuffled.push_back(files[i]);
    const std::vector<uint32_t> again = splitIntoShards(shuffled, total, durations);
    for (size_t k = 0; k < order.size(); ++k) ASSERT_EQ(again[k], shard[order[k]]) << "trial " << trial;
  }
}

// An environment of the given variables only.
Environment environment(std::map<std::string, std::string> vars) {
  return [vars = std::move(vars)](const char* name) -> const char* {
    const auto v = vars.find(name);
    return v == vars.end() ? nullptr : v->second.c_str();
  };
}

TEST(Shards, EveryRunnersConventionAsksForTheSameShard) {
  for (uint32_t total = 1; total <= 6; ++total)
    for (uint32_t index = 0; index < total; ++index) {
      const std::string i0 = std::to_string(index), i1 = std::to_string(index + 1), n = std::to_string(total);
      const std::vector<std::pair<std::string, std::optional<Shard>>> asks = {
          {"flag", askedShard(i1 + "/" + n, "", environment({}))},
          {"Bazel", askedShard("", "", environment({{"TEST_SHARD_INDEX", i0}, {"TEST_TOTAL_SHARDS", n}}))},
          {"GoogleTest", askedShard("", "", environment({{"GTEST_SHARD_INDEX", i0}, {"GTEST_TOTAL_SHARDS", n}}))},
          {"GitLab", askedShard("", "", environment({{"CI_NODE_INDEX", i1}, {"CI_NODE_TOTAL", n}}))},
          {"Kubernetes", askedShard("", n, environment({{"JOB_COMPLETION_INDEX", i0}}))},
          // Two conventions that agree (Bazel sets GoogleTest's variables too) are one shard.
          {"both", askedShard("", "",
                              environment({{"TEST_SHARD_INDEX", i0},
                                           {"TEST_TOTAL_SHARDS", n},
                                           {"GTEST_SHARD_INDEX", i0},
                                           {"GTEST_TOTAL_SHARDS", n}}))},
      };
      for (const auto& [how, shard] : asks) {
        ASSERT_TRUE(shard.has_value()) << how;
        EXPECT_EQ(shard->index, index) << how;
        EXPECT_EQ(shard->total, total) << how;
      }
    }
  EXPECT_FALSE(askedShard("", "", environment({})).has_value());
  // The flag wins over the environment: a run inside a sharded job that must run its suite whole.
  const std::optional<Shard> whole =
      askedShard("1/1", "", environment({{"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "4"}}));
  ASSERT_TRUE(whole.has_value());
  EXPECT_EQ(whole->total, 1u);
  // GitLab gives a `parallel: matrix` job the same variables, but each such job runs a suite of its
  // own; only `parallel: N` names its jobs "<name> I/N".
  EXPECT_FALSE(
      askedShard(
          "", "",
          environment({{"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "3"}, {"CI_JOB_NAME", "scenarios: [cube, bookworm]"}}))
          .has_value());
  const std::optional<Shard> parallel = askedShard(
      "", "", environment({{"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "3"}, {"CI_JOB_NAME", "scenarios 2/3"}}));
  ASSERT_TRUE(parallel.has_value());
  EXPECT_EQ(parallel->index, 1u);
  // GitLab says CI_NODE_TOTAL=1 in every job that is not parallel: the whole suite.
  EXPECT_FALSE(askedShard("", "", environment({{"CI_NODE_TOTAL", "1"}})).has_value());
}

TEST(Shards, AShardThatIsNoShardIsRefusedByName) {
  const std::vector<std::tuple<std::string, std::string, std::map<std::string, std::string>, std::string>> cases = {
      {"0/4", "", {}, "--shard 0/4: the shard must be a whole number from 1 to 4, got '0'"},
      {"5/4", "", {}, "--shard 5/4: the shard must be a whole number from 1 to 4"},
      {"x/4", "", {}, "--shard x/4: the shard must be a whole number"},
      {"1/0", "", {}, "--shard 1/0: the number of shards must be a whole number from 1 to 100000, got '0'"},
      {"3", "", {}, "--shard 3: expected I/N"},
      {"",
       "",
       {{"TEST_SHARD_INDEX", "4"}, {"TEST_TOTAL_SHARDS", "4"}},
       "TEST_SHARD_INDEX=4, TEST_TOTAL_SHARDS=4: the shard must be a whole number from 0 to 3"},
      {"",
       "",
       {{"CI_NODE_INDEX", "0"}, {"CI_NODE_TOTAL", "2"}},
       "CI_NODE_INDEX=0, CI_NODE_TOTAL=2: the shard must be a whole number from 1 to 2"},
      {"", "", {{"GTEST_SHARD_INDEX", "1"}}, "GoogleTest: GTEST_TOTAL_SHARDS is not set but GTEST_SHARD_INDEX is"},
      {"", "4", {}, "--shards 4: the shard's index comes from JOB_COMPLETION_INDEX"},
      {"",
       "",
       {{"TEST_SHARD_INDEX", "0"}, {"TEST_TOTAL_SHARDS", "4"}, {"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "4"}},
       "two ways of asking for a shard disagree: Bazel asks for 1/4, GitLab for 2/4"},
  };
  for (const auto& [flag, total, vars, message] : cases) {
    try {
      askedShard(flag, total, environment(vars));
      ADD_FAILURE() << "accepted: " << flag << " " << total;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
    }
  }
}

TEST(Shards, TheSuitesIdentityIsItsFilesInAnyOrder) {
  EXPECT_EQ(suiteIdentity({"b.lua", "a.lua"}), suiteIdentity({"a.lua", "b.lua"}));
  EXPECT_NE(suiteIdentity({"a.lua", "b.lua"}), suiteIdentity({"a.lua", "c.lua"}));
  EXPECT_EQ(suiteIdentity({"a.lua", "b.lua"}).rfind("2 ", 0), 0u);
}

}  // namespace
}  // namespace platon::app
