// `platon play scene.lua [--frames N] [--input run.replay] [--record out.replay] [--watch] [--fast]`
#pragma once

namespace platon::app {

int playCommand(int argc, char** argv);  // argv[0] is "play"

}  // namespace platon::app
