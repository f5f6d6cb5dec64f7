// `platon run [-j N] [--junit report.xml] [--timeout S] scenario.lua...`
#pragma once

namespace platon::app {

int runCommand(int argc, char** argv);  // argv[0] is "run"

}  // namespace platon::app
