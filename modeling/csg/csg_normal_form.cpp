#include "modeling/csg/csg_normal_form.h"

#include <algorithm>

namespace qacc {
namespace {

using Sum = std::vector<CsgProduct>;

struct Expander {
  const CsgTree& tree;
  std::size_t maxProducts;
  bool complete = true;

  // Intersection of two sums: every pair of products, merged; empty products dropped.
  Sum conjoin(const Sum& a, const Sum& b) {
    Sum out;
    for (const CsgProduct& p : a)
      for (const CsgProduct& q : b) {
        if (out.size() >= maxProducts) {
          complete = false;
          return out;
        }
        CsgProduct r;
        std::merge(p.begin(), p.end(), q.begin(), q.end(), std::back_inserter(r),
                   [](const CsgLiteral& x, const CsgLiteral& y) {
                     return x.primitive != y.primitive ? x.primitive < y.primitive : x.complement < y.complement;
                   });
        r.erase(std::unique(r.begin(), r.end()), r.end());
        bool empty = false;
        for (std::size_t i = 1; i < r.size(); ++i) empty |= r[i].primitive == r[i - 1].primitive;
        if (!empty) out.push_back(std::move(r));
      }
    return out;
  }

  Sum disjoin(Sum a, const Sum& b) {
    for (const CsgProduct& p : b) {
      if (a.size() >= maxProducts) {
        complete = false;
        break;
      }
      a.push_back(p);
    }
    return a;
  }

  // The node (or its complement) as a sum of products.
  Sum expand(int n, bool negate) {
    if (!complete) return {};
    const CsgNode& node = tree.nodes[std::size_t(n)];
    if (node.op == CsgNode::Op::Leaf) return {CsgProduct{CsgLiteral{node.primitive, negate}}};
    // Each child with the sign it has in the node: a difference complements all but the first.
    std::vector<std::pair<int, bool>> terms;
    for (std::size_t i = 0; i < node.children.size(); ++i)
      terms.emplace_back(node.children[i], node.op == CsgNode::Op::Difference && i > 0);
    // union, or the complement of an intersection or difference (De Morgan), is a sum.
    const bool isSum = (node.op == CsgNode::Op::Union) != negate;
    Sum acc;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const Sum t = expand(terms[i].first, terms[i].second != negate);
      acc = i == 0 ? t : isSum ? disjoin(std::move(acc), t) : conjoin(acc, t);
    }
    return acc;
  }
};

}  // namespace

std::size_t CsgNormalForm::maxLiterals() const {
  std::size_t k = 0;
  for (const CsgProduct& p : products) k = std::max(k, p.size());
  return k;
}

std::size_t CsgNormalForm::passes() const {
  std::size_t n = 0;
  for (const CsgProduct& p : products) n += p.size() * p.size();
  return n;
}

CsgNormalForm normalForm(const CsgTree& tree, std::size_t maxProducts) {
  CsgNormalForm f;
  if (tree.root < 0) return f;
  Expander e{tree, maxProducts};
  f.products = e.expand(tree.root, false);
  f.complete = e.complete;
  return f;
}

}  // namespace qacc
