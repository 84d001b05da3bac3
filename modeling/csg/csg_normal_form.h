// The normal form of a CSG tree (Goldfeather et al., IEEE CG&A 1989): a union of products,
// each the intersection of leaves and complemented leaves, as a board that draws one
// product at a time needs it. Built by distributing intersection over union and De
// Morgan's laws (A − B = A ∩ ¬B); products that hold a leaf and its complement are empty
// and dropped, repeated literals merged. The size can grow exponentially with nested
// differences of unions; past `maxProducts` the form is not built (`complete` = false).
#pragma once
#include <cstddef>
#include <vector>

#include "modeling/csg/csg_tree.h"

namespace qacc {

struct CsgLiteral {
  int primitive = -1;     // a leaf's index into Scene::primitives
  bool complement = false;
  bool operator==(const CsgLiteral& o) const { return primitive == o.primitive && complement == o.complement; }
};

using CsgProduct = std::vector<CsgLiteral>;  // sorted by primitive

struct CsgNormalForm {
  std::vector<CsgProduct> products;
  bool complete = true;
  std::size_t maxLiterals() const;
  // Goldfeather's depth-layer method draws each literal's surface once per product and
  // classifies it against every literal of the product: k² passes for k literals.
  std::size_t passes() const;
};

CsgNormalForm normalForm(const CsgTree& tree, std::size_t maxProducts = 100000);

}  // namespace qacc
