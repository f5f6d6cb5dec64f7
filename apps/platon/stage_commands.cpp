#include "stage_commands.h"

#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "commands.h"
#include "engine_registry.h"
#include "level_argument.h"
#include "platon/core/mesh_source.h"
#include "platon/core/scene.h"
#include "platon/files/write_file.h"
#include "platon/stage/level_check.h"
#include "platon/stage/net.h"

namespace platon::app {
namespace {

std::string where(const stage::SourcePosition& p) {
  std::string s = stage::describe(p);
  return s.empty() ? s : s.substr(0, s.size() - 2);
}

// The stage a level is drawn on; a mesh level's through the meshes plugin.
stage::Stage stageFor(const stage::Level& level) {
  if (level.solid) return stage::platonicStageOf(level);
  core::SystemRegistry registry = engineRegistry(Presentation::Headless);
  core::Scene scene;
  const std::unique_ptr<core::System> meshes = registry.create("meshes", scene);
  return core::meshStageOf(level, *meshes->meshSource());
}

// A level given in any of its forms (level_argument.h), read with its scene's tag words (the
// game's and its mods').
stage::Level levelOfArgument(const std::string& argument) {
  LevelArgument level;
  try {
    level = levelArgument(argument);
  } catch (const std::runtime_error& e) {
    std::string why = e.what();
    if (why.rfind(argument + ": ", 0) == 0) why.erase(0, argument.size() + 2);  // the place says it
    throw stage::StageError({argument, 0, 0}, why);
  }
  if (level.levelFile.empty()) throw stage::StageError({level.scene, 0, 0}, "the scene names no level file");
  std::shared_ptr<const stage::TagTable> tags = stage::gameTags();
  if (!level.scene.empty()) {
    try {
      tags = core::sceneTags(level.scene, engineRegistry(Presentation::Headless));
    } catch (const stage::StageError&) {
      throw;
    } catch (const std::exception& e) {  // a mod that declares its tags wrongly
      throw stage::StageError({level.scene, 0, 0}, e.what());
    }
  }
  return stage::parseLevel(stage::readLevelFile(level.levelFile), level.levelFile, tags);
}

}  // namespace

int checkCommand(int argc, char** argv) {
  if (argc < 2) {
    return usageError("check");
  }
  int errors = 0, warnings = 0;
  for (int i = 1; i < argc; ++i) {
    std::string file = argv[i];
    try {
      const stage::Level level = levelOfArgument(file);
      file = level.file;
      const stage::CheckReport report = checkLevel(level, stageFor(level));
      for (const auto& f : report.errors) std::printf("%s: error: %s\n", where(f.where).c_str(), f.message.c_str());
      for (const auto& f : report.warnings) std::printf("%s: warning: %s\n", where(f.where).c_str(), f.message.c_str());
      errors += static_cast<int>(report.errors.size());
      warnings += static_cast<int>(report.warnings.size());
      if (report.errors.empty()) std::printf("%s: ok (%zu faces)\n", file.c_str(), level.faces.size());
    } catch (const stage::StageError& e) {
      std::printf("%s: error: %s\n", where(e.where()).c_str(), e.reason().c_str());
      ++errors;
    }
  }
  std::printf("%d level(s): %d error(s), %d warning(s)\n", argc - 1, errors, warnings);
  return errors ? 1 : 0;
}

std::vector<std::string> levelErrors(const std::string& argument) {
  std::vector<std::string> out;
  try {
    const stage::Level level = levelOfArgument(argument);
    for (const auto& f : checkLevel(level, stageFor(level)).errors) out.push_back(where(f.where) + ": " + f.message);
  } catch (const stage::StageError& e) {
    out.push_back(where(e.where()) + ": " + e.reason());
  } catch (const std::exception& e) {
    out.emplace_back(e.what());
  }
  return out;
}

int netCommand(int argc, char** argv) {
  std::string what, out;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-o") == 0 && i + 1 < argc)
      out = argv[++i];
    else
      what = argv[i];
  }
  if (what.empty() || out.empty()) {
    return usageError("net");
  }
  try {
    stage::Stage s;
    std::string title;
    std::optional<stage::Level> level;
    if (const auto solid = stage::solidFromName(what)) {
      s = stage::platonicStage(*solid, 1000);
      title = std::string(stage::solidName(*solid)) + ": " + std::to_string(s.faceCount()) + " faces";
    } else {
      level = levelOfArgument(what);
      s = stageFor(*level);
      title = level->file;
    }
    if (const std::string why =
            files::saveWhole(out, stage::netSvg(s, stage::unfold(s), title, level ? &*level : nullptr), "the picture");
        !why.empty())
      throw stage::StageError({out, 0, 0}, why.substr(out.size() + 2));
  } catch (const stage::StageError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace platon::app
