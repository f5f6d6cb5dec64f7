// JUnit XML reports, the format CI systems read (GitHub, GitLab, Jenkins, Bazel): what `platon run
// --junit` writes, what `--durations` reads back to balance shards, what `platon merge` joins.
// Written and read with tinyxml2; only the parts those tools use: one <testsuite>, its
// <properties>, and a <testcase> per scenario with its time and any <failure>.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace platon::app {

struct JunitCase {
  std::string name;  // the scenario's path, as given
  double seconds = 0;
  bool passed = true;
  std::string message;  // a failure's text (its first line is the failure's message attribute)
};

struct JunitReport {
  std::vector<JunitCase> cases;
  std::map<std::string, std::string> properties;
  double seconds = 0;  // the whole run
};

// Writes the report (every text shown as core::visibleText shows it). Returns false when the file
// cannot be written.
bool writeJunit(const std::string& path, const JunitReport& report);

// Reads a report: every <testcase> of every <testsuite>, and the first suite's properties. Throws
// std::runtime_error "path: why" for a file that is no JUnit report (or no regular file, or more
// than 256 MB).
JunitReport readJunit(const std::string& path);

}  // namespace platon::app
