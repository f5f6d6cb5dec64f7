#include "stage_commands.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "engine_registry.h"
#include "platon/core/mesh_source.h"
#include "platon/core/scene.h"
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

}  // namespace

int checkCommand(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: platon check level.level...\n");
    return 2;
  }
  int errors = 0, warnings = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string file = argv[i];
    try {
      const stage::Level level = stage::parseLevel(stage::readLevelFile(file), file);
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

int netCommand(int argc, char** argv) {
  std::string what, out;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-o") == 0 && i + 1 < argc)
      out = argv[++i];
    else
      what = argv[i];
  }
  if (what.empty() || out.empty()) {
    std::fprintf(stderr, "usage: platon net TETRAHEDRON|HEXAHEDRON|...|level.level -o net.svg\n");
    return 2;
  }
  try {
    stage::Stage s;
    std::string title;
    if (const auto solid = stage::solidFromName(what)) {
      s = stage::platonicStage(*solid, 1000);
      title = std::string(stage::solidName(*solid)) + ": " + std::to_string(s.faceCount()) + " faces";
    } else {
      const stage::Level level = stage::parseLevel(stage::readLevelFile(what), what);
      s = stageFor(level);
      title = what;
    }
    std::ofstream file(out);
    file << stage::netSvg(s, stage::unfold(s), title);
    if (!file) throw stage::StageError({out, 0, 0}, "cannot write the picture");
  } catch (const stage::StageError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace platon::app
