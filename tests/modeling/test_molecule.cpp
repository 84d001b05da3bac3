// Molecules: PDB parsing (fixed columns, element detection), radii, bond inference
// (against a brute-force count), ball-and-stick / spacefill primitives, real PDB files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <set>
#include <string>

#include "modeling/modelers/molecule.h"

using namespace qacc;

namespace {

// One ATOM/HETATM record in the fixed PDB columns.
std::string atomLine(const char* rec, int serial, const char* name, const char* res, double x, double y, double z,
                     const char* element) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%-6s%5d %-4s %3s A%4d    %8.3f%8.3f%8.3f%6.2f%6.2f          %2s", rec, serial,
                name, res, 1, x, y, z, 1.0, 0.0, element);
  return std::string(buf) + "\n";
}

// Tetrahedral directions.
const Eigen::Vector3d kTetra[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};

std::size_t bruteForceBonds(const std::vector<Atom>& atoms) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < atoms.size(); ++i)
    for (std::size_t j = i + 1; j < atoms.size(); ++j) {
      const double d = (atoms[i].position - atoms[j].position).norm();
      if (d > 0.4 && d < covalentRadius(atoms[i].element) + covalentRadius(atoms[j].element) + 0.4) ++n;
    }
  return n;
}

}  // namespace

TEST(Molecule, WaterHasTwoBonds) {
  const std::string pdb = atomLine("HETATM", 1, " O", "HOH", 0, 0, 0, " O") +
                          atomLine("HETATM", 2, " H1", "HOH", 0.957, 0, 0, " H") +
                          atomLine("HETATM", 3, " H2", "HOH", -0.240, 0.927, 0, " H");
  const Molecule m = parsePdb(pdb, "water.pdb");
  ASSERT_EQ(m.atoms.size(), 3u);
  EXPECT_EQ(m.atoms[0].element, "O");
  EXPECT_EQ(m.atoms[1].element, "H");
  EXPECT_TRUE(m.atoms[0].hetero);
  EXPECT_EQ(m.atoms[0].residue, "HOH");
  EXPECT_EQ(m.atoms[2].serial, 3);
  EXPECT_NEAR(m.atoms[1].position.x(), 0.957, 1e-12);
  // O-H at 0.957 Å are bonds; H-H at 1.51 Å exceeds 0.31 + 0.31 + 0.4 = 1.02 Å.
  ASSERT_EQ(m.bonds.size(), 2u);
  EXPECT_EQ(m.bonds[0], std::make_pair(0, 1));
  EXPECT_EQ(m.bonds[1], std::make_pair(0, 2));
}

TEST(Molecule, EthaneHasSevenBonds) {
  // C-C 1.54 Å along x, three H per carbon at 1.09 Å in tetrahedral directions.
  const Eigen::Vector3d c1(0, 0, 0), c2(1.54, 0, 0);
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 1).normalized();  // kTetra[0] points to the other C
  // Orthonormal R with R * axis = x (a rotation or reflection: both keep the distances).
  Eigen::Matrix3d R;
  const Eigen::Vector3d u = axis.cross(Eigen::Vector3d::UnitZ()).normalized();
  R.row(0) = axis.transpose();
  R.row(1) = u.transpose();
  R.row(2) = axis.cross(u).transpose();
  std::string pdb = atomLine("ATOM", 1, " C1", "ETH", c1.x(), c1.y(), c1.z(), " C") +
                    atomLine("ATOM", 2, " C2", "ETH", c2.x(), c2.y(), c2.z(), " C");
  int serial = 3;
  for (int k = 1; k < 4; ++k) {
    const Eigen::Vector3d h1 = c1 + 1.09 * (R * kTetra[k].normalized());
    const Eigen::Vector3d h2 = c2 - 1.09 * (R * kTetra[k].normalized());
    pdb += atomLine("ATOM", serial++, " H", "ETH", h1.x(), h1.y(), h1.z(), " H");
    pdb += atomLine("ATOM", serial++, " H", "ETH", h2.x(), h2.y(), h2.z(), " H");
  }
  const Molecule m = parsePdb(pdb, "ethane.pdb");
  ASSERT_EQ(m.atoms.size(), 8u);
  EXPECT_EQ(m.bonds.size(), 7u);
  int cc = 0;
  for (const auto& [i, j] : m.bonds)
    if (m.atoms[std::size_t(i)].element == "C" && m.atoms[std::size_t(j)].element == "C") ++cc;
  EXPECT_EQ(cc, 1);
}

TEST(Molecule, GridBondsMatchBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 30);
  const char* elements[] = {"C", "N", "O", "H", "S", "Fe"};
  std::vector<Atom> atoms;
  for (int i = 0; i < 3000; ++i) {
    Atom a;
    a.element = elements[i % 6];
    a.position = {u(rng), u(rng), u(rng)};
    atoms.push_back(a);
  }
  const auto bonds = inferBonds(atoms);
  EXPECT_GT(bonds.size(), 100u);
  EXPECT_EQ(bonds.size(), bruteForceBonds(atoms));
  std::set<std::pair<int, int>> unique(bonds.begin(), bonds.end());
  EXPECT_EQ(unique.size(), bonds.size());
  for (const auto& [i, j] : bonds) EXPECT_LT(i, j);
}

TEST(Molecule, ElementDetection) {
  EXPECT_EQ(normalizeElement("FE"), "Fe");
  EXPECT_EQ(normalizeElement(" c"), "C");
  EXPECT_EQ(normalizeElement("Xx"), "");
  // Columns 77-78 absent or not an element (old files put a segment id there): use the name.
  std::string pdb;
  pdb += "ATOM      1  CA  ALA A   1       0.000   0.000   0.000  1.00  0.00      1ABC 101\n";  // C alpha, not Ca
  pdb += "HETATM    2 FE   HEM A   2      10.000   0.000   0.000  1.00  0.00\n";                // iron, column 13
  pdb += "ATOM      3 HG12 VAL A   3      20.000   0.000   0.000  1.00  0.00\n";                // hydrogen, not Hg
  pdb += "ATOM      4 1HB  ALA A   4      30.000   0.000   0.000  1.00  0.00\n";                // digit prefix
  pdb += "HETATM    5 CA    CA A   5      40.000   0.000   0.000  1.00  0.00          CA\n";  // calcium ion
  const Molecule m = parsePdb(pdb, "e.pdb");
  ASSERT_EQ(m.atoms.size(), 5u);
  EXPECT_EQ(m.atoms[0].element, "C");
  EXPECT_EQ(m.atoms[1].element, "Fe");
  EXPECT_EQ(m.atoms[2].element, "H");
  EXPECT_EQ(m.atoms[3].element, "H");
  EXPECT_EQ(m.atoms[4].element, "Ca");
  EXPECT_TRUE(m.bonds.empty());
}

TEST(Molecule, AlternateLocationsAndModels) {
  std::string pdb;
  pdb += "ATOM      1  CB AALA A   1       0.000   0.000   0.000  0.50  0.00           C\n";
  pdb += "ATOM      2  CB BALA A   1       0.300   0.000   0.000  0.50  0.00           C\n";
  pdb += "ATOM      3  CA  ALA A   1       1.530   0.000   0.000  1.00  0.00           C\n";
  pdb += "ENDMDL\n";
  pdb += "ATOM      4  CA  ALA A   1       3.000   0.000   0.000  1.00  0.00           C\n";
  const Molecule m = parsePdb(pdb, "alt.pdb");
  ASSERT_EQ(m.atoms.size(), 2u);  // B location and the second model dropped
  EXPECT_EQ(m.atoms[0].serial, 1);
  EXPECT_EQ(m.atoms[1].serial, 3);
  EXPECT_EQ(m.bonds.size(), 1u);
}

TEST(Molecule, ParseErrorsNameFileAndLine) {
  auto err = [](const std::string& text) {
    try {
      parsePdb(text, "m.pdb");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(err("REMARK x\nATOM      1  CA  ALA A   1       0.000   0.000\n").rfind("m.pdb:2: ATOM/HETATM record shorter", 0),
            0u);
  EXPECT_EQ(err("ATOM      1  CA  ALA A   1       0.000   abcde   0.000  1.00  0.00           C\n")
                .rfind("m.pdb:1: bad y coordinate 'abcde'", 0),
            0u);
  EXPECT_EQ(err("ATOM      1  QQ  ALA A   1       0.000   0.000   0.000  1.00  0.00\n")
                .rfind("m.pdb:1: cannot determine the element", 0),
            0u);
}

TEST(Molecule, RadiiAndColours) {
  EXPECT_DOUBLE_EQ(vdwRadius("C"), 1.70);
  EXPECT_DOUBLE_EQ(vdwRadius("N"), 1.55);
  EXPECT_DOUBLE_EQ(vdwRadius("O"), 1.52);
  EXPECT_DOUBLE_EQ(vdwRadius("H"), 1.20);
  EXPECT_DOUBLE_EQ(vdwRadius("S"), 1.80);
  EXPECT_DOUBLE_EQ(covalentRadius("C"), 0.76);
  EXPECT_DOUBLE_EQ(covalentRadius("N"), 0.71);
  EXPECT_DOUBLE_EQ(covalentRadius("O"), 0.66);
  EXPECT_DOUBLE_EQ(covalentRadius("H"), 0.31);
  EXPECT_DOUBLE_EQ(covalentRadius("S"), 1.05);
  EXPECT_GT(cpkColor("O").x(), 0.9);  // red
  EXPECT_LT(cpkColor("O").z(), 0.1);
  EXPECT_GT(cpkColor("N").z(), 0.9);  // blue
}

TEST(Molecule, BallAndStickPrimitives) {
  Molecule m;
  Atom o, h;
  o.element = "O";
  h.element = "H";
  h.position = {0.96, 0, 0};
  m.atoms = {o, h};
  m.bonds = inferBonds(m.atoms);
  ASSERT_EQ(m.bonds.size(), 1u);
  MoleculeDisplay d;  // ball and stick, 0.25 × vdW, bond radius 0.15
  const auto prims = moleculePrimitives(m, d, [](const std::string& e) { return e == "O" ? 1 : 2; });
  ASSERT_EQ(prims.size(), 4u);  // 2 spheres + 2 half-bond cylinders
  EXPECT_NEAR(prims[0].quadric.eval({0.25 * 1.52, 0, 0}), 0, 1e-12);
  EXPECT_NEAR(prims[1].quadric.eval({0.96, 0.25 * 1.20, 0}), 0, 1e-12);
  EXPECT_EQ(prims[2].material, 1);  // O half
  EXPECT_EQ(prims[3].material, 2);  // H half
  // The O half covers x in [0, 0.48] at radius 0.15.
  EXPECT_NEAR(prims[2].quadric.eval({0.3, 0.15, 0}), 0, 1e-12);
  auto inside = [](const Primitive& p, const Eigen::Vector3d& x) {
    for (const auto& hs : p.clip)
      if (!hs.contains(x)) return false;
    return true;
  };
  EXPECT_TRUE(inside(prims[2], {0.3, 0, 0}));
  EXPECT_FALSE(inside(prims[2], {0.6, 0, 0}));
  EXPECT_TRUE(inside(prims[3], {0.6, 0, 0}));
  // Same material on both ends: one cylinder.
  const auto same = moleculePrimitives(m, d, [](const std::string&) { return 3; });
  EXPECT_EQ(same.size(), 3u);
  d.style = MoleculeStyle::Spacefill;
  d.atom_scale = 1.0;
  const auto fill = moleculePrimitives(m, d, [](const std::string&) { return 1; });
  ASSERT_EQ(fill.size(), 2u);
  EXPECT_NEAR(fill[0].quadric.eval({1.52, 0, 0}), 0, 1e-12);
}

TEST(Molecule, RealProteinFiles) {
  const std::string hpv = "/usr/share/pymol/data/tut/1hpv.pdb";
  const std::string pept = "/usr/share/pymol/data/demo/pept.pdb";
  ASSERT_TRUE(std::filesystem::exists(hpv)) << "install Debian's pymol-data (tools/deps.sh does)";
  const Molecule m = readPdb(hpv);
  EXPECT_EQ(m.atoms.size(), 1631u);  // 1516 protein + 35 inhibitor atoms and 80 waters, no hydrogens
  std::size_t waters = 0;
  for (const auto& a : m.atoms) waters += a.residue == "HOH";
  EXPECT_EQ(waters, 80u);
  // Heavy-atom protein: every non-water atom has 1 to 4 bonds, and bonds ≈ atoms.
  std::vector<int> degree(m.atoms.size(), 0);
  for (const auto& [i, j] : m.bonds) {
    ++degree[std::size_t(i)];
    ++degree[std::size_t(j)];
    const double d = (m.atoms[std::size_t(i)].position - m.atoms[std::size_t(j)].position).norm();
    EXPECT_GT(d, 1.0);
    EXPECT_LT(d, 2.0);
  }
  int isolated = 0, over = 0;
  for (std::size_t k = 0; k < m.atoms.size(); ++k) {
    if (m.atoms[k].residue == "HOH") continue;
    isolated += degree[k] == 0;
    over += degree[k] > 4;
  }
  EXPECT_EQ(isolated, 0);
  EXPECT_EQ(over, 0);
  EXPECT_GT(m.bonds.size(), 1551u);
  EXPECT_LT(m.bonds.size(), 1700u);

  const Molecule p = readPdb(pept);
  EXPECT_EQ(p.atoms.size(), 107u);
  EXPECT_GE(p.bonds.size(), 106u);  // a connected peptide
}
