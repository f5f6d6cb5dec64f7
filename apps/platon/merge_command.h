// `platon merge -o all.xml shard.xml...`: the JUnit reports of the shards of one suite joined into
// one, checked: every shard 1..N there once, all of the same suite, every scenario run exactly once.
#pragma once

namespace platon::app {

int mergeCommand(int argc, char** argv);  // argv[0] is "merge"

}  // namespace platon::app
