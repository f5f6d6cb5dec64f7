// Levels that travel: `platon pack` makes a package of a level and a run that finishes it;
// `platon install` unpacks one into the player's levels folder only once the level checks and that
// run, replayed headless in a worker process with a time limit, reaches the goal with every hash
// the same. Until then it lies in a staging folder beside the levels (.installing-PID), which is
// removed whatever happens.
#include "pack_command.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "commands.h"
#include "engine_registry.h"
#include "level_argument.h"
#include "platon/core/error.h"
#include "platon/core/manifest.h"
#include "platon/core/replay.h"
#include "platon/core/visible_text.h"
#include "platon/package/package.h"
#include "platon/script/scenario.h"
#include "run_command.h"
#include "save_file.h"
#include "stage_commands.h"

namespace platon::app {
namespace {

namespace fs = std::filesystem;

// A folder removed when it goes out of scope.
struct Staging {
  fs::path path;
  ~Staging() {
    std::error_code error;
    fs::remove_all(path, error);
  }
};

// The checks a level passes to be packed or installed: `platon check` finds no error, and
// finish.replay, replayed headless in a worker (at most `timeout` seconds), keeps every recorded
// hash and reaches the goal. `root` holds `folder`; a scenario beside it (verify.lua) does the run.
void verify(const fs::path& root, const std::string& folder, double timeout) {
  const fs::path level = root / folder;
  const std::vector<std::string> errors = levelErrors((level / "scene.lua").string());
  if (!errors.empty()) {
    std::string all;
    for (const std::string& e : errors) all += "\n  " + e;
    throw std::runtime_error("the level has errors:" + all);
  }
  const core::Replay replay = core::readReplay((level / "finish.replay").string());
  if (replay.frames() == 0) throw std::runtime_error("finish.replay plays no frame");
  // The replay's input and hashes as a scenario that must also reach the goal by its last frame.
  core::Replay fromRoot = replay;
  fromRoot.scene = folder + "/scene.lua";
  script::ScenarioResult none;
  none.frames = replay.frames();
  std::string scenario = script::scenarioFromReplay(fromRoot, none, "finish.replay");
  const std::string expect = "  expect = {\n";
  scenario.insert(scenario.find(expect) + expect.size(), "    goal_by = " + std::to_string(replay.frames()) + ",\n");
  files::saveWholeOrThrow((root / "verify.lua").string(), scenario, "the package's check");
  const script::ScenarioResult r = runIsolated((root / "verify.lua").string(), timeout);
  if (!r.passed) throw std::runtime_error("finish.replay does not finish the level: " + r.message);
}

double secondsArgument(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!end || *end || !(v > 0 && v <= 86400))
    throw std::runtime_error("--timeout " + text + ": want seconds, 0 to 86400");
  return v;
}

}  // namespace

std::string userLevelsFolder() { return userFolder("data") + "/levels"; }

// The run a package carries: a replay, or a scenario (a play-test the editor kept with K,
// test_N.lua) played headless to the recording it makes; it must pass.
core::Replay runOf(const std::string& path) {
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".lua") != 0) return core::readReplay(path);
  script::RunOptions options;
  options.record = true;
  options.pluginFolders = pluginFolders();
  const script::ScenarioResult r = script::runScenario(path, options);
  if (!r.passed) throw std::runtime_error(path + ": the scenario does not pass, so its run is no finish: " + r.message);
  if (!r.recorded) throw std::runtime_error(path + ": the scenario recorded no run");
  std::printf("the run of %s (%llu frames)\n", path.c_str(), static_cast<unsigned long long>(r.recorded->frames()));
  return *r.recorded;
}

int packCommand(int argc, char** argv) {
  std::string level, replayPath, out;
  double timeout = 120;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--replay" && i + 1 < argc)
        replayPath = argv[++i];
      else if (a == "-o" && i + 1 < argc)
        out = argv[++i];
      else if (a == "--timeout" && i + 1 < argc)
        timeout = secondsArgument(argv[++i]);
      else if (level.empty() && !a.empty() && a[0] != '-')
        level = a;
      else
        return usageError("pack");
    }
    if (level.empty() || replayPath.empty()) return usageError("pack");
    const LevelArgument found = levelArgument(level);
    if (found.scene.empty()) throw std::runtime_error(level + ": no scene.lua: a package is a level's folder");
    const fs::path source = fs::path(found.scene).parent_path();
    const std::string folder = fs::absolute(source).lexically_normal().filename().string();
    if (!package::plainName(folder))
      throw std::runtime_error(source.string() + ": the folder's name is not plain (letters, digits, '.', '-', '_')");
    if (out.empty()) out = folder + ".platon";
    // Staged as it will be installed: the folder's files and the run as finish.replay.
    Staging staging{fs::temp_directory_path() / ("platon_pack_" + std::to_string(::getpid()))};
    fs::remove_all(staging.path);
    fs::create_directories(staging.path / folder);
    fs::copy(source, staging.path / folder, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    core::Replay replay = runOf(replayPath);
    replay.scene = "scene.lua";
    fs::remove(staging.path / folder / "finish.replay");
    core::writeReplay(replay, (staging.path / folder / "finish.replay").string());
    for (const std::string& file : package::removeUncarriedFiles((staging.path / folder).string()))
      std::printf("left out %s\n", core::visibleText(file).c_str());
    verify(staging.path, folder, timeout);
    const std::string name = core::loadManifest(found.scene).name;
    const package::PackageManifest m = package::writePackage(staging.path.string(), folder, name, out);
    // Names from content (the level's name) are shown through the visible-text filter: no terminal escapes.
    std::printf("%s: %s (%zu files, %llu frames to the goal), hash %s\n", core::visibleText(out).c_str(),
                core::visibleText(name).c_str(), m.files.size(), static_cast<unsigned long long>(replay.frames()),
                m.hash.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::errorReport(e).c_str());
    return 1;
  }
}

int installCommand(int argc, char** argv) {
  std::string archive, levels = userLevelsFolder();
  double timeout = 120;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--levels" && i + 1 < argc)
        levels = argv[++i];
      else if (a == "--timeout" && i + 1 < argc)
        timeout = secondsArgument(argv[++i]);
      else if (archive.empty() && !a.empty() && a[0] != '-')
        archive = a;
      else
        return usageError("install");
    }
    if (archive.empty()) return usageError("install");
    fs::create_directories(levels);
    Staging staging{fs::path(levels) / (".installing-" + std::to_string(::getpid()))};
    fs::remove_all(staging.path);
    const package::PackageManifest m = package::readPackage(archive, staging.path.string());
    const fs::path target = fs::path(levels) / m.folder;
    if (fs::exists(fs::symlink_status(target)))
      throw std::runtime_error(target.string() + ": a level of this folder's name is installed (remove it first)");
    try {
      for (const std::string& file : package::removeUncarriedFiles((staging.path / m.folder).string()))
        std::printf("%s: refused %s\n", core::visibleText(archive).c_str(), core::visibleText(file).c_str());
      verify(staging.path, m.folder, timeout);
    } catch (const std::exception& e) {
      throw std::runtime_error(archive + ": " + e.what());
    }
    fs::rename(staging.path / m.folder, target);
    std::printf("%s: installed %s in %s (the title screen lists it)\n", core::visibleText(archive).c_str(),
                core::visibleText(m.name).c_str(), core::visibleText(target.string()).c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::errorReport(e).c_str());
    return 1;
  }
}

}  // namespace platon::app
