// The csg scene type: the tree it builds and the trees it refuses (file and JSON path).
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "modeling/loader/scene_loader.h"

using namespace qacc;

namespace {

Scene load(const std::string& objects) {
  return parseScene(R"({"format": "qacc-scene/1", "camera": {"eye": [0, 0, 8], "target": [0, 0, 0]},
    "materials": {"red": {"color": [1, 0, 0]}, "blue": {"color": [0, 0, 1]}},
    "objects": [)" + objects + "]}",
                    "t.json", ".");
}

// The error's message without its text position, which every error of the scene's text ends
// with (json_location.h; tested there).
std::string errorOf(const std::string& objects) {
  try {
    load(objects);
  } catch (const SceneError& e) {
    static const std::regex position(R"( \(line [0-9]+, column [0-9]+\)$)");
    const std::string msg = e.what();
    EXPECT_TRUE(std::regex_search(msg, position)) << msg;
    return std::regex_replace(msg, position, "");
  }
  return "";
}

}  // namespace

TEST(CsgObject, BuildsTreeWithPolaritiesMaterialsAndNesting) {
  const Scene s = load(R"({"type": "sphere", "radius": 1},
    {"type": "csg", "op": "difference", "material": "red", "transform": {"translate": [1, 0, 0]}, "children": [
      {"type": "sphere", "radius": 1, "solid": true},
      {"type": "csg", "op": "intersection", "material": "blue", "children": [
        {"type": "cylinder", "base": [0, 0, -2], "top": [0, 0, 2], "radius": 0.5, "solid": true},
        {"type": "cylinder", "base": [-2, 0, 0], "top": [2, 0, 0], "radius": 0.5, "solid": true}]}]})");
  ASSERT_EQ(s.csg_trees.size(), 1u);
  const CsgTree& t = s.csg_trees[0];
  EXPECT_EQ(t.object, 1);
  EXPECT_EQ(t.depth(), 3);
  const std::vector<int> leaves = t.leafPrimitives();
  ASSERT_EQ(leaves, (std::vector<int>{1, 2, 3}));
  const std::vector<int> pol = t.polarities();
  int plus = 0, minus = 0;
  for (std::size_t n = 0; n < t.nodes.size(); ++n)
    if (t.nodes[n].op == CsgNode::Op::Leaf) (pol[n] > 0 ? plus : minus)++;
  EXPECT_EQ(plus, 1);
  EXPECT_EQ(minus, 2);
  EXPECT_EQ(s.materials[std::size_t(s.primitives[1].material)].name, "red");   // the csg object's
  EXPECT_EQ(s.materials[std::size_t(s.primitives[2].material)].name, "blue");  // the nested csg's
  for (int i = 1; i <= 3; ++i) {
    EXPECT_EQ(s.primitives[std::size_t(i)].object, 1);
    EXPECT_TRUE(s.primitives[std::size_t(i)].solid);
  }
  // The outer transform moved every leaf: the first sphere's centre is at x = 1.
  EXPECT_LT(s.primitives[1].quadric.eval(Eigen::Vector3d(1, 0, 0)), 0);
  EXPECT_GT(s.primitives[1].quadric.eval(Eigen::Vector3d(-0.5, 0, 0)), 0);
}

TEST(CsgObject, NamedChildIsInstanced) {
  const Scene s = load(R"({"type": "csg", "op": "union", "children": [
      {"type": "sphere", "radius": 1, "solid": true, "name": "ball"}, "ball"]})");
  ASSERT_EQ(s.csg_trees.size(), 1u);
  EXPECT_EQ(s.csg_trees[0].leafPrimitives().size(), 2u);
}

TEST(CsgObject, RefusesBadTreesWithFileAndPath) {
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": []})"),
            "t.json: /objects/0/children: a csg object needs at least one child");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union"})"), "t.json: /objects/0: missing required key 'children'");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "xor", "children": [{"type": "sphere", "radius": 1, "solid": true}]})"),
            "t.json: /objects/0/op: unknown csg op 'xor' (expected union, intersection or difference)");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "difference", "children": [
      {"type": "sphere", "radius": 1, "solid": true}, {"type": "sphere", "radius": 0.5}]})"),
            "t.json: /objects/0/children/1: a csg child must be a solid (give it \"solid\": true)");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": [
      {"type": "csg", "op": "intersection", "children": [{"type": "sphere", "radius": 1}]}]})"),
            "t.json: /objects/0/children/0/children/0: a csg child must be a solid (give it \"solid\": true)");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": ["nothing"]})"),
            "t.json: /objects/0/children/0: no object named 'nothing' in this csg tree");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": [
      {"type": "csg", "name": "A", "op": "union", "children": [
        {"type": "csg", "name": "B", "op": "difference", "children": [{"type": "sphere", "radius": 1, "solid": true}, "A"]}]}]})"),
            "t.json: /objects/0/children/0/children/0/children/1: cycle of references: A -> B -> A");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": [
      {"type": "sphere", "radius": 1, "solid": true, "name": "x"}, {"type": "sphere", "radius": 2, "solid": true, "name": "x"}]})"),
            "t.json: /objects/0/children/1/name: name 'x' is used twice in this csg tree");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": [
      {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})"),
            "t.json: /objects/0/children/0: a csg child must be a solid (give it \"solid\": true)");
  EXPECT_EQ(errorOf(R"({"type": "csg", "op": "union", "children": [{"type": "sphere", "radius": 1, "solid": true, "colour": 1}]})"),
            "t.json: /objects/0/children/0/colour: unknown key 'colour'");
}
