// `platon run [-j N] [--junit report.xml] [--timeout S] [--record dir] scenario.lua|run.replay...`
#pragma once
#include <string>

#include "platon/script/scenario.h"

namespace platon::app {

// Runs one scenario or replay in a worker process, killed past `timeout` seconds: a crash or a
// hang of an untrusted level's is the worker's (`platon install` checks a package's run so).
script::ScenarioResult runIsolated(const std::string& file, double timeout);

int runCommand(int argc, char** argv);  // argv[0] is "run" (or "replay")
// `platon scenario run.replay [-o scenario.lua]`: a regression scenario from a replay.
int scenarioCommand(int argc, char** argv);

}  // namespace platon::app
