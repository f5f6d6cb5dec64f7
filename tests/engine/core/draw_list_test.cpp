// Drawing between two simulation steps: shapes that exist in both pictures move the fraction of
// the way; shapes that changed kind, face or point count, and shapes new in the later picture,
// are drawn as they are in it.
#include "platon/core/draw_list.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

using namespace platon::core;

TEST(DrawListBetween, MatchingShapesMoveTheFractionOfTheWay) {
  DrawList a(true), b(true);
  a.circle(Place::onFace(2), {0, 0}, 10, {});
  b.circle(Place::onFace(2), {100, 40}, 20, {});
  const Point2 pa[] = {{0, 0}, {10, 0}, {0, 10}}, pb[] = {{20, 0}, {30, 0}, {20, 10}};
  a.polygon(Place::onFace(2), pa, {});
  b.polygon(Place::onFace(2), pb, {});
  a.text(Place::onScreen(), {0, 0}, "old", 10, {});
  b.text(Place::onScreen(), {10, 10}, "new", 10, {});
  const DrawList m = DrawList::between(a, b, 0.25f);
  ASSERT_EQ(m.shapes().size(), 3u);
  EXPECT_FLOAT_EQ(m.shapes()[0].at.x, 25);
  EXPECT_FLOAT_EQ(m.shapes()[0].at.y, 10);
  EXPECT_FLOAT_EQ(m.shapes()[0].size, 12.5f);
  EXPECT_FLOAT_EQ(m.points()[m.shapes()[1].first + 1].x, 15);
  EXPECT_EQ(m.text(m.shapes()[2]), "new");  // the later picture's text, moved
  EXPECT_FLOAT_EQ(m.shapes()[2].at.x, 2.5f);
}

TEST(DrawListBetween, ShapesThatChangedAreDrawnAsTheyAreNow) {
  DrawList a(true), b(true);
  a.circle(Place::onFace(1), {0, 0}, 10, {});  // the player crossed onto face 2: no sliding across
  b.circle(Place::onFace(2), {500, 500}, 10, {});
  b.circle(Place::onFace(2), {7, 7}, 3, {});  // new this step
  const DrawList m = DrawList::between(a, b, 0.5f);
  ASSERT_EQ(m.shapes().size(), 2u);
  EXPECT_FLOAT_EQ(m.shapes()[0].at.x, 500);
  EXPECT_FLOAT_EQ(m.shapes()[1].at.x, 7);
  const DrawList same = DrawList::between(b, b, 0.3f);
  EXPECT_FLOAT_EQ(same.shapes()[0].at.x, 500);
}

// A frame's list is bounded (what scripts draw is work and memory outside every Lua limit): past
// its limits a shape is dropped and the call says so.
TEST(DrawListLimits, ShapesPointsAndTextPastTheLimitsAreDropped) {
  DrawList list(true);
  for (size_t i = 0; i < DrawList::kMaxShapes; ++i) ASSERT_TRUE(list.circle(Place::onFace(0), {0, 0}, 1, {}));
  EXPECT_FALSE(list.circle(Place::onFace(0), {0, 0}, 1, {}));
  EXPECT_FALSE(list.text(Place::onScreen(), {0, 0}, "x", 10, {}));
  EXPECT_EQ(list.shapes().size(), DrawList::kMaxShapes);
  DrawList text(true);
  const std::string big(DrawList::kMaxTextBytes / 2, 'x');
  EXPECT_TRUE(text.text(Place::onScreen(), {0, 0}, big, 10, {}));
  EXPECT_TRUE(text.text(Place::onScreen(), {0, 0}, big, 10, {}));
  EXPECT_FALSE(text.text(Place::onScreen(), {0, 0}, "x", 10, {}));
  DrawList points(true);
  const std::vector<Point2> many(256, Point2{});
  size_t drawn = 0;
  while (points.polygon(Place::onFace(0), many, {})) ++drawn;
  EXPECT_EQ(drawn, DrawList::kMaxPoints / 256);
  DrawList off;  // disabled: records nothing, refuses nothing
  EXPECT_TRUE(off.circle(Place::onFace(0), {0, 0}, 1, {}));
  EXPECT_TRUE(off.shapes().empty());
}
