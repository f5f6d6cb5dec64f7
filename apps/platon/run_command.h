// `platon run [-j N] [--junit report.xml] [--timeout S] [--record dir] scenario.lua|run.replay...`
#pragma once

namespace platon::app {

int runCommand(int argc, char** argv);  // argv[0] is "run" (or "replay")
// `platon scenario run.replay [-o scenario.lua]`: a regression scenario from a replay.
int scenarioCommand(int argc, char** argv);

}  // namespace platon::app
