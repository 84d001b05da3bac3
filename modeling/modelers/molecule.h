// Molecules from PDB files (design §5): ATOM/HETATM records of the first model, bonds
// inferred from covalent radii, space-filling or ball-and-stick display as quadrics.
//
// Parsing uses the fixed PDB columns: name 13-16, altLoc 17 (only ' ' and the first
// alternate location are kept), residue name 18-20, chain 22, residue number 23-26,
// x/y/z 31-54, element 77-78 (when it names an element; otherwise derived from the atom
// name: a name starting in column 13 is a two-letter element such as "FE", unless it is a
// 4-character hydrogen name).
// Radii: van der Waals from Bondi (1964) (2.0 Å for elements Bondi does not list);
// covalent from Cordero et al. (2008) (1.5 Å for unlisted ones). Two atoms are bonded
// when 0.4 Å < d < r1 + r2 + 0.4 Å (found with a uniform spatial grid).
// Colours are the CPK convention (sRGB, converted to linear for materials).
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "modeling/loader/object_registry.h"
#include "modeling/loader/view_cull_count.h"

namespace qacc {

struct Atom {
  int serial = 0;
  std::string name;      // atom name, trimmed ("CA")
  std::string residue;   // residue name ("PRO")
  char chain = ' ';
  int residue_number = 0;
  std::string element;   // capitalised symbol ("C", "Fe")
  bool hetero = false;   // HETATM record
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // Å
};

struct Molecule {
  std::vector<Atom> atoms;
  std::vector<std::pair<int, int>> bonds;  // atom indices, first < second, sorted
};

// Reads a PDB file (throws std::runtime_error "PATH:LINE: problem", or "PATH: problem").
Molecule readPdb(const std::string& path, std::size_t max_bytes = Limits{}.max_input_bytes);
// Parses PDB text (name used in messages). Bonds are inferred.
Molecule parsePdb(const std::string& text, const std::string& name);

// Bond inference: pairs with 0.4 Å < d < r1 + r2 + 0.4 Å (covalent radii).
std::vector<std::pair<int, int>> inferBonds(const std::vector<Atom>& atoms);

// Element data.
double vdwRadius(const std::string& element);       // Å, Bondi 1964
double covalentRadius(const std::string& element);  // Å, Cordero et al. 2008
Eigen::Vector3d cpkColor(const std::string& element);  // sRGB in [0, 1]
// "C", "Fe" from any case ("FE" → "Fe"); empty if not a known element symbol.
std::string normalizeElement(const std::string& symbol);

enum class MoleculeStyle { Spacefill, BallAndStick };

struct MoleculeDisplay {
  MoleculeStyle style = MoleculeStyle::BallAndStick;
  double atom_scale = 0.25;   // sphere radius = atom_scale × van der Waals radius
  double bond_radius = 0.15;  // Å (ball-and-stick only)
};

// Primitives of a molecule: one sphere per atom, and for ball-and-stick two cylinders per
// bond, each half in its atom's material (one cylinder when both halves share a material).
// `material_of(element)` gives the material index of an element (asked for every atom,
// seen or not, so materials do not depend on the view). With a `view` (view culling,
// ObjectContext::view), an atom whose ball or a bond whose cylinder's box hull misses it is
// not built (counted in `count`).
std::vector<Primitive> moleculePrimitives(const Molecule& m, const MoleculeDisplay& d,
                                          const std::function<int(const std::string&)>& material_of,
                                          const ViewVolume* view = nullptr, ViewCullCount* count = nullptr);

// Scene builder for "pdb": {"file", "style": "spacefill" | "ball_and_stick",
// "atom_scale", "bond_radius", "center", "waters"}. Materials "pdb:<element>" are appended
// to the scene (or reused when the scene defines them); an explicit object "material"
// colours every atom and bond with it instead.
std::vector<Primitive> buildPdb(const JsonNode& o, ObjectContext& ctx);

}  // namespace qacc
