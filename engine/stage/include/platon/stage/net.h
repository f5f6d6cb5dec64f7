// A stage's net: its faces unfolded flat, edge to edge, as a level designer draws on them; and the
// net as an SVG picture with each face's number, axes and "down" (docs/level-format.md shows one
// for every solid).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "platon/stage/level.h"
#include "platon/stage/stage.h"

namespace platon::stage {

// Where face i lies in the net: its frame's origin and x axis (a unit vector); its y axis is the
// x axis turned a quarter left (faces are seen from outside, so none is mirrored).
struct NetFace {
  Eigen::Vector2d origin, xAxis;
  int attachedTo = -1;  // the face it was unfolded from (-1 for face 0)

  Eigen::Vector2d place(double x, double y) const {
    return origin + x * xAxis + y * Eigen::Vector2d(-xAxis.y(), xAxis.x());
  }
};

// Unfolds the faces from face 0 (laid in its own frame), each face joined to the first face in
// number order that already lies flat and leaves it room. Faces never overlap in the result.
std::vector<NetFace> unfold(const Stage& stage);

// Which face, and which of its edges, lies across each edge of each face, as a Markdown table
// (docs/level-format.md shows one per Platonic solid; a test checks they are today's).
std::string neighbourTable(const Stage& stage);

// The net as a self-contained SVG document. With a level (on this stage), also its lines coloured
// by tag (one-way lines dashed), its start and goal, and each face's own gravity as its "down".
std::string netSvg(const Stage& stage, const std::vector<NetFace>& net, const std::string& title,
                   const Level* level = nullptr);

}  // namespace platon::stage
