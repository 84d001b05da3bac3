// The `csg` scene type (docs/SCENES.md): {"type": "csg", "op": "union" | "intersection" |
// "difference", "children": [OBJECT or "NAME", ...]}. Children are built by the loader's own
// object path (buildObject: their builder, clip, transform, material, solid) and must be
// solids; a child that is a string names another object of the same tree (by its "name"),
// which is instanced there; a name that refers to an object being built is a cycle.
// The primitives of every leaf are returned to the loader in tree order; the tree itself
// goes to Scene::csg_trees with absolute primitive indices (the loader appends the
// returned primitives right after the ones already in the scene).
#include <map>
#include <string>
#include <vector>

#include "modeling/csg/csg_tree.h"
#include "modeling/loader/object_registry.h"
#include "modeling/loader/scene_loader.h"

namespace qacc {
namespace {

struct Step {
  bool index = false;
  std::string key;
  std::size_t i = 0;
};

class TreeBuilder;
// The builder of the top-level `csg` object being loaded; nested `csg` children (loaded
// through buildObject, which calls the registered builder again) add to its tree.
thread_local TreeBuilder* active = nullptr;

class TreeBuilder {
 public:
  TreeBuilder(const JsonNode& top, ObjectContext& ctx)
      : top_(top), ctx_(ctx), first_(ctx.scene.primitives.size()) {
    tree_.object = int(ctx.scene.objects.size());
    collectNames(top, {});
  }

  // Nodes of a `csg` object (its op and children); returns the node index.
  int combination(const JsonNode& n) {
    const JsonNode opNode = n.at("op");
    const std::string opName = opNode.string();
    CsgNode node;
    if (opName == "union") node.op = CsgNode::Op::Union;
    else if (opName == "intersection") node.op = CsgNode::Op::Intersection;
    else if (opName == "difference") node.op = CsgNode::Op::Difference;
    else opNode.fail("unknown csg op '" + opName + "' (expected union, intersection or difference)");
    const JsonNode children = n.at("children");
    if (!children.isArray()) children.fail("expected an array of solid objects");
    if (children.size() == 0) children.fail("a csg object needs at least one child");
    std::string name;
    if (auto nm = n.get("name")) name = nm->string();
    if (!name.empty()) building_.push_back(name);
    for (std::size_t i = 0; i < children.size(); ++i) node.children.push_back(child(children[i]));
    if (!name.empty()) building_.pop_back();
    tree_.nodes.push_back(node);
    return int(tree_.nodes.size()) - 1;
  }

  void setRoot(int root) { tree_.root = root; }
  void setLastNested(int node) { lastNested_ = node; }
  // Absolute primitive index of the next primitive a nested child will return.
  std::size_t nextPrimitive() const { return first_ + prims_.size(); }
  const CsgTree& tree() const { return tree_; }
  std::vector<Primitive>& primitives() { return prims_; }

 private:
  const JsonNode& top_;
  ObjectContext& ctx_;
  std::size_t first_;
  CsgTree tree_;
  std::vector<Primitive> prims_;
  std::map<std::string, std::vector<Step>> named_;
  std::vector<std::string> building_;  // names of the objects on the path being built
  int lastNested_ = -1;

  // Every "name" of an object of the tree, with the steps that lead to it from the top.
  void collectNames(const JsonNode& n, const std::vector<Step>& steps) {
    const auto& j = n.json();
    if (!j.is_object()) return;
    if (j.contains("name") && j["name"].is_string() && !steps.empty()) {
      const std::string name = j["name"].get<std::string>();
      if (named_.count(name)) n.at("name").fail("name '" + name + "' is used twice in this csg tree");
      named_[name] = steps;
    }
    if (!j.contains("children") || !j["children"].is_array()) return;
    if (!(j.contains("type") && j["type"] == "csg")) return;
    const JsonNode children = n.at("children");
    for (std::size_t i = 0; i < children.size(); ++i) {
      std::vector<Step> s = steps;
      s.push_back(Step{false, "children", 0});
      s.push_back(Step{true, "", i});
      collectNames(children[i], s);
    }
  }

  JsonNode follow(const std::vector<Step>& steps) const {
    JsonNode n = top_;
    for (const Step& s : steps) n = s.index ? n[s.i] : n.at(s.key);
    return n;
  }

  int child(const JsonNode& c) {
    if (c.json().is_string()) {
      const std::string name = c.string();
      for (std::size_t k = 0; k < building_.size(); ++k)
        if (building_[k] == name) {
          std::string cycle;
          for (std::size_t m = k; m < building_.size(); ++m) cycle += building_[m] + " -> ";
          c.fail("cycle of references: " + cycle + name);
        }
      auto it = named_.find(name);
      if (it == named_.end()) c.fail("no object named '" + name + "' in this csg tree");
      building_.push_back(name);
      const int node = child(follow(it->second));
      building_.pop_back();
      return node;
    }
    if (!c.isObject()) c.fail("expected a solid object or the name of one");
    const bool nested = c.json().contains("type") && c.json()["type"] == "csg";
    std::string name;
    if (!nested && c.json().contains("name") && c.json()["name"].is_string()) name = c.json()["name"].get<std::string>();
    if (!name.empty()) building_.push_back(name);
    const std::size_t base = prims_.size();
    lastNested_ = -1;
    std::vector<Primitive> part = buildObject(c, ctx_, tree_.object);
    if (!name.empty()) building_.pop_back();
    if (part.empty()) c.fail("a csg child must produce at least one solid primitive");
    for (const Primitive& p : part)
      if (!p.solid) c.fail("a csg child must be a solid (give it \"solid\": true)");
    prims_.insert(prims_.end(), part.begin(), part.end());
    if (nested) return lastNested_;
    // A child of several primitives is their union.
    CsgNode u;
    u.op = CsgNode::Op::Union;
    for (std::size_t i = 0; i < part.size(); ++i) {
      CsgNode leaf;
      leaf.primitive = int(first_ + base + i);
      tree_.nodes.push_back(leaf);
      u.children.push_back(int(tree_.nodes.size()) - 1);
    }
    if (u.children.size() == 1) return u.children[0];
    tree_.nodes.push_back(u);
    return int(tree_.nodes.size()) - 1;
  }
};

std::vector<Primitive> buildCsg(const JsonNode& o, ObjectContext& ctx) {
  if (active) {
    // A nested csg child: its nodes join the top-level tree; its primitives go back through
    // the loader (which applies the child's own transform and material) to the parent,
    // which puts them back at the same place.
    std::vector<Primitive>& all = active->primitives();
    const std::size_t before = all.size();
    active->setLastNested(active->combination(o));
    std::vector<Primitive> part(all.begin() + std::ptrdiff_t(before), all.end());
    all.resize(before);
    return part;
  }
  TreeBuilder builder(o, ctx);
  struct Activation {
    explicit Activation(TreeBuilder* b) { active = b; }
    ~Activation() { active = nullptr; }
  } activation(&builder);
  builder.setRoot(builder.combination(o));
  ctx.scene.csg_trees.push_back(builder.tree());
  ctx.note = std::to_string(builder.tree().leafPrimitives().size()) + " solid leaves, depth " +
             std::to_string(builder.tree().depth());
  return std::move(builder.primitives());
}

[[maybe_unused]] const bool kRegistered = registerObjectTypes({{"csg", buildCsg}});

}  // namespace
}  // namespace qacc
