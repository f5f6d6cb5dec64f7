#pragma once

namespace platon::app {

// `platon shot LEVEL [--frame N] [--size WxH] [--input run.replay] --out file.png`
int shotCommand(int argc, char** argv);

}  // namespace platon::app
