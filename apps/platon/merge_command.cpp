#include "merge_command.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.h"
#include "junit.h"
#include "shard.h"

namespace platon::app {
namespace {

int mergeUsage() { return usageError("merge"); }

// "I/N" -> {I, N}, 1 <= I <= N.
std::pair<unsigned long, unsigned long> shardNumbers(const std::string& text, const std::string& file) {
  unsigned long i = 0, n = 0;
  char slash = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%lu%c%lu%n", &i, &slash, &n, &used) != 3 || slash != '/' || i < 1 || i > n ||
      static_cast<size_t>(used) != text.size())
    throw std::runtime_error(file + ": its platon.shard property is '" + text + "', not I/N");
  return {i, n};
}

// The merged report, or a runtime_error naming what is wrong.
JunitReport merge(const std::vector<std::string>& files) {
  std::string suite, suiteFile;
  unsigned long total = 0;
  std::map<unsigned long, std::string> shards;  // shard number -> the file that reported it
  std::map<std::string, std::string> ranIn;     // scenario -> the file that reported it
  JunitReport all;
  for (const std::string& file : files) {
    JunitReport r = readJunit(file);
    const auto s = r.properties.find("platon.suite");
    const auto sh = r.properties.find("platon.shard");
    if (s == r.properties.end() || sh == r.properties.end())
      throw std::runtime_error(file + ": not a report of `platon run` (no platon.suite and platon.shard properties)");
    const auto [index, of] = shardNumbers(sh->second, file);
    if (suite.empty()) {
      suite = s->second, suiteFile = file, total = of;
    } else if (s->second != suite || of != total) {
      throw std::runtime_error(file + " and " + suiteFile + " are shards of different suites (" + s->second + ", " +
                               std::to_string(of) + " shards; " + suite + ", " + std::to_string(total) + " shards)");
    }
    if (const auto [at, fresh] = shards.emplace(index, file); !fresh)
      throw std::runtime_error("shard " + sh->second + " is given twice: " + at->second + " and " + file);
    for (JunitCase& c : r.cases) {
      if (const auto [at, fresh] = ranIn.emplace(c.name, file); !fresh)
        throw std::runtime_error(c.name + " ran twice: in " + at->second + " and in " + file);
      all.cases.push_back(std::move(c));
    }
    all.seconds += r.seconds;
  }
  std::string missing;
  for (unsigned long i = 1; i <= total; ++i)
    if (!shards.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(total);
  if (!missing.empty()) throw std::runtime_error("shard(s) " + missing + " missing");
  // The suite is its files: the scenarios the reports name must be exactly those the split was of.
  std::vector<std::string> names;
  for (const JunitCase& c : all.cases) names.push_back(c.name);
  if (suiteIdentity(names) != suite) {
    const unsigned long expected = std::strtoul(suite.c_str(), nullptr, 10);
    throw std::runtime_error(
        "the reports name " + std::to_string(names.size()) + " scenarios, not the " + std::to_string(expected) +
        " of the suite they were split from" +
        (names.size() < expected ? " (a shard that stopped early?)" : " (a shard that ran other files?)"));
  }
  all.properties["platon.suite"] = suite;
  all.properties["platon.shard"] = "1/1";
  all.properties["platon.merged"] = std::to_string(total) + " shards";
  return all;
}

}  // namespace

int mergeCommand(int argc, char** argv) {
  std::string out;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "-o" || a == "--out") && i + 1 < argc)
      out = argv[++i];
    else if (!a.empty() && a[0] == '-')
      return mergeUsage();
    else
      files.push_back(a);
  }
  if (out.empty() || files.empty()) return mergeUsage();
  JunitReport all;
  try {
    all = merge(files);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "platon merge: %s\n", e.what());
    return 1;
  }
  if (!writeJunit(out, all)) return std::fprintf(stderr, "platon merge: %s: cannot write\n", out.c_str()), 1;
  int failed = 0;
  for (const JunitCase& c : all.cases) failed += c.passed ? 0 : 1;
  std::printf("%zu scenarios from %zu shards, each run once, %d failed: %s\n", all.cases.size(), files.size(), failed,
              out.c_str());
  return failed ? 1 : 0;
}

}  // namespace platon::app
