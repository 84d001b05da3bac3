#include "modeling/modelers/molecule.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/support/bounded_file.h"

namespace qacc {
namespace {

struct ElementData {
  const char* symbol;
  double vdw;       // Bondi 1964 (0: not listed)
  double covalent;  // Cordero et al. 2008 (C: sp3; Mn, Fe, Co: low spin)
  unsigned rgb;     // CPK colour (sRGB)
};

// clang-format off
const ElementData kElements[] = {
    {"H", 1.20, 0.31, 0xFFFFFF}, {"He", 1.40, 0.28, 0xD9FFFF}, {"Li", 1.82, 1.28, 0xCC80FF},
    {"Be", 0, 0.96, 0xC2FF00},   {"B", 0, 0.84, 0xFFB5B5},     {"C", 1.70, 0.76, 0x909090},
    {"N", 1.55, 0.71, 0x3050F8}, {"O", 1.52, 0.66, 0xFF0D0D},  {"F", 1.47, 0.57, 0x90E050},
    {"Ne", 1.54, 0.58, 0xB3E3F5}, {"Na", 2.27, 1.66, 0xAB5CF2}, {"Mg", 1.73, 1.41, 0x8AFF00},
    {"Al", 0, 1.21, 0xBFA6A6},   {"Si", 2.10, 1.11, 0xF0C8A0}, {"P", 1.80, 1.07, 0xFF8000},
    {"S", 1.80, 1.05, 0xFFFF30}, {"Cl", 1.75, 1.02, 0x1FF01F}, {"Ar", 1.88, 1.06, 0x80D1E3},
    {"K", 2.75, 2.03, 0x8F40D4}, {"Ca", 0, 1.76, 0x3DFF00},    {"Sc", 0, 1.70, 0xE6E6E6},
    {"Ti", 0, 1.60, 0xBFC2C7},   {"V", 0, 1.53, 0xA6A6AB},     {"Cr", 0, 1.39, 0x8A99C7},
    {"Mn", 0, 1.39, 0x9C7AC7},   {"Fe", 0, 1.32, 0xE06633},    {"Co", 0, 1.26, 0xF090A0},
    {"Ni", 1.63, 1.24, 0x50D050}, {"Cu", 1.40, 1.32, 0xC88033}, {"Zn", 1.39, 1.22, 0x7D80B0},
    {"Ga", 1.87, 1.22, 0xC28F8F}, {"Ge", 0, 1.20, 0x668F8F},   {"As", 1.85, 1.19, 0xBD80E3},
    {"Se", 1.90, 1.20, 0xFFA100}, {"Br", 1.85, 1.20, 0xA62929}, {"Kr", 2.02, 1.16, 0x5CB8D1},
    {"Rb", 0, 2.20, 0x702EB0},   {"Sr", 0, 1.95, 0x00FF00},    {"Y", 0, 1.90, 0x94FFFF},
    {"Zr", 0, 1.75, 0x94E0E0},   {"Mo", 0, 1.54, 0x54B5B5},    {"Ru", 0, 1.46, 0x248F8F},
    {"Rh", 0, 1.42, 0x0A7D8C},   {"Pd", 1.63, 1.39, 0x006985}, {"Ag", 1.72, 1.45, 0xC0C0C0},
    {"Cd", 1.58, 1.44, 0xFFD98F}, {"In", 1.93, 1.42, 0xA67573}, {"Sn", 2.17, 1.39, 0x668080},
    {"Sb", 0, 1.39, 0x9E63B5},   {"Te", 2.06, 1.38, 0xD47A00}, {"I", 1.98, 1.39, 0x940094},
    {"Xe", 2.16, 1.40, 0x429EB0}, {"Cs", 0, 2.44, 0x57178F},   {"Ba", 0, 2.15, 0x00C900},
    {"W", 0, 1.62, 0x2194D6},    {"Pt", 1.72, 1.36, 0xD0D0E0}, {"Au", 1.66, 1.36, 0xFFD123},
    {"Hg", 1.55, 1.32, 0xB8B8D0}, {"Tl", 1.96, 1.45, 0xA6544D}, {"Pb", 2.02, 1.46, 0x575961},
    {"Bi", 0, 1.48, 0x9E4FB5},   {"U", 1.86, 1.96, 0x008FFF},
};
// clang-format on

constexpr double kDefaultVdw = 2.0;
constexpr double kDefaultCovalent = 1.5;
constexpr double kBondTolerance = 0.4;  // Å
constexpr double kMinBond = 0.4;        // Å

const ElementData* findElement(const std::string& symbol) {
  for (const auto& e : kElements)
    if (symbol == e.symbol) return &e;
  return nullptr;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(' ');
  return s.substr(b, e - b + 1);
}

std::string columns(const std::string& line, std::size_t first, std::size_t last) {  // 1-based inclusive
  if (line.size() < first) return "";
  return line.substr(first - 1, std::min(last, line.size()) - first + 1);
}

[[noreturn]] void lineError(const std::string& name, std::size_t line, const std::string& problem) {
  throw std::runtime_error(name + ":" + std::to_string(line) + ": " + problem);
}

double coordinate(const std::string& line, std::size_t first, std::size_t last, const std::string& name,
                  std::size_t lineNo, const char* axis) {
  const std::string s = trim(columns(line, first, last));
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v))
    lineError(name, lineNo, std::string("bad ") + axis + " coordinate '" + s + "' in columns " +
                                std::to_string(first) + "-" + std::to_string(last));
  return v;
}

// Element of an atom whose columns 77-78 do not name one, from its name field (cols 13-16).
std::string elementFromName(const std::string& field) {
  std::string f = field;
  f.resize(4, ' ');
  const char c0 = f[0], c1 = f[1];
  if (c0 == ' ' || std::isdigit(static_cast<unsigned char>(c0))) return normalizeElement(std::string(1, c1));
  if ((c0 == 'H' || c0 == 'h') && f[3] != ' ') return "H";  // 4-character hydrogen names (HG12)
  const std::string two = normalizeElement(std::string{c0, c1});
  if (!two.empty() && std::isalpha(static_cast<unsigned char>(c1))) return two;
  return normalizeElement(std::string(1, c0));
}

Eigen::Vector3d rgbOf(unsigned rgb) {
  return {((rgb >> 16) & 0xFF) / 255.0, ((rgb >> 8) & 0xFF) / 255.0, (rgb & 0xFF) / 255.0};
}

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

}  // namespace

std::string normalizeElement(const std::string& symbol) {
  const std::string t = trim(symbol);
  if (t.empty() || t.size() > 2) return "";
  std::string s;
  s += char(std::toupper(static_cast<unsigned char>(t[0])));
  if (t.size() == 2) s += char(std::tolower(static_cast<unsigned char>(t[1])));
  return findElement(s) ? s : "";
}

double vdwRadius(const std::string& element) {
  const ElementData* e = findElement(element);
  return e && e->vdw > 0 ? e->vdw : kDefaultVdw;
}

double covalentRadius(const std::string& element) {
  const ElementData* e = findElement(element);
  return e ? e->covalent : kDefaultCovalent;
}

Eigen::Vector3d cpkColor(const std::string& element) {
  const ElementData* e = findElement(element);
  return rgbOf(e ? e->rgb : 0xFF1493);  // unknown: deep pink
}

Molecule parsePdb(const std::string& text, const std::string& name) {
  Molecule mol;
  std::istringstream in(text);
  std::string line;
  std::size_t lineNo = 0;
  char firstAlt = ' ';
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string rec = columns(line, 1, 6);
    if (rec == "ENDMDL" || rec == "END" || rec == "END   ") break;  // first model only
    const bool hetero = rec == "HETATM";
    if (rec != "ATOM  " && !hetero) continue;
    if (line.size() < 54) lineError(name, lineNo, "ATOM/HETATM record shorter than 54 columns");
    const char alt = line[16];
    if (alt != ' ') {
      if (firstAlt == ' ') firstAlt = alt;
      if (alt != firstAlt) continue;  // keep one alternate location
    }
    Atom a;
    a.hetero = hetero;
    a.serial = std::atoi(columns(line, 7, 11).c_str());
    const std::string nameField = columns(line, 13, 16);
    a.name = trim(nameField);
    a.residue = trim(columns(line, 18, 20));
    a.chain = line.size() >= 22 ? line[21] : ' ';
    a.residue_number = std::atoi(columns(line, 23, 26).c_str());
    a.position = {coordinate(line, 31, 38, name, lineNo, "x"), coordinate(line, 39, 46, name, lineNo, "y"),
                  coordinate(line, 47, 54, name, lineNo, "z")};
    a.element = normalizeElement(columns(line, 77, 78));
    if (a.element.empty()) a.element = elementFromName(nameField);
    if (a.element.empty())
      lineError(name, lineNo, "cannot determine the element of atom '" + a.name + "' (columns 77-78 and 13-16)");
    mol.atoms.push_back(a);
  }
  mol.bonds = inferBonds(mol.atoms);
  return mol;
}

Molecule readPdb(const std::string& path, std::size_t max_bytes) {
  return parsePdb(readModelFile(path, max_bytes, "PDB file"), path);
}

std::vector<std::pair<int, int>> inferBonds(const std::vector<Atom>& atoms) {
  std::vector<std::pair<int, int>> bonds;
  if (atoms.size() < 2) return bonds;
  std::vector<double> radius(atoms.size());
  double rmax = 0;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    radius[i] = covalentRadius(atoms[i].element);
    rmax = std::max(rmax, radius[i]);
  }
  // A cell at least as large as the longest possible bond: bonded atoms are in the same or
  // adjacent cells.
  const double cell = 2 * rmax + kBondTolerance;
  Eigen::Vector3d lo = atoms[0].position;
  for (const auto& a : atoms) lo = lo.cwiseMin(a.position);
  // Cell indices are 64-bit (coordinates of 1e7 and more give indices beyond 32 bits: the
  // former int cells and 21-bit packed key overflowed, undefined behaviour). A PDB coordinate
  // has 8 columns, so |p - lo| < 2e100 and the index fits once it is below 2^62; above that,
  // atoms that far apart are never bonded, and they share the last cell, which costs only
  // distance tests. The key mixes the three indices with unsigned (wrapping) arithmetic:
  // a collision only adds distance tests, never a wrong bond.
  constexpr double kMaxIndex = 4.0e18;
  auto cellOf = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d c = (p - lo) / cell;
    std::array<long long, 3> r{};
    for (int a = 0; a < 3; ++a) r[std::size_t(a)] = static_cast<long long>(std::min(std::floor(c[a]), kMaxIndex));
    return r;
  };
  auto key = [](long long x, long long y, long long z) {
    std::uint64_t h = static_cast<std::uint64_t>(x);
    h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(y);
    h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(z);
    return h;
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  grid.reserve(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const auto c = cellOf(atoms[i].position);
    grid[key(c[0], c[1], c[2])].push_back(int(i));
  }
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const auto c = cellOf(atoms[i].position);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          if (c[0] + dx < 0 || c[1] + dy < 0 || c[2] + dz < 0) continue;
          auto it = grid.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == grid.end()) continue;
          for (int j : it->second) {
            if (j <= int(i)) continue;
            const double d = (atoms[i].position - atoms[std::size_t(j)].position).norm();
            if (d > kMinBond && d < radius[i] + radius[std::size_t(j)] + kBondTolerance)
              bonds.emplace_back(int(i), j);
          }
        }
  }
  std::sort(bonds.begin(), bonds.end());
  return bonds;
}

std::vector<Primitive> moleculePrimitives(const Molecule& m, const MoleculeDisplay& d,
                                          const std::function<int(const std::string&)>& material_of,
                                          const ViewVolume* view, ViewCullCount* count) {
  ViewCullCount local(view != nullptr);
  ViewCullCount& seen = count ? *count : local;
  // A cylinder of radius r on the segment ab lies in the hull of the cubes of half-side r
  // around a and b (segment ⊕ ball ⊂ segment ⊕ cube).
  auto cylinderMayBeSeen = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
    if (!view) return true;
    std::array<Eigen::Vector3d, 16> hull;
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d c(k & 1 ? r : -r, k & 2 ? r : -r, k & 4 ? r : -r);
      hull[std::size_t(k)] = a + c;
      hull[std::size_t(k) + 8] = b + c;
    }
    return view->mayContain(hull.data(), hull.size());
  };
  std::vector<Primitive> out;
  std::vector<int> mat(m.atoms.size());
  for (std::size_t i = 0; i < m.atoms.size(); ++i) {
    const Atom& a = m.atoms[i];
    mat[i] = material_of(a.element);
    const double radius = d.atom_scale * vdwRadius(a.element);
    if (!seen.keep(!view || view->mayContainBall(a.position, radius))) continue;
    Primitive p = makeSphere(a.position, radius);
    p.material = mat[i];
    out.push_back(p);
  }
  if (d.style != MoleculeStyle::BallAndStick) return out;
  for (const auto& [i, j] : m.bonds) {
    const Eigen::Vector3d& a = m.atoms[std::size_t(i)].position;
    const Eigen::Vector3d& b = m.atoms[std::size_t(j)].position;
    if (mat[std::size_t(i)] == mat[std::size_t(j)]) {
      if (!seen.keep(cylinderMayBeSeen(a, b, d.bond_radius))) continue;
      Primitive p = makeCylinder(a, b, d.bond_radius);
      p.material = mat[std::size_t(i)];
      out.push_back(p);
    } else {
      const Eigen::Vector3d mid = 0.5 * (a + b);
      if (seen.keep(cylinderMayBeSeen(a, mid, d.bond_radius))) {
        Primitive p = makeCylinder(a, mid, d.bond_radius);
        p.material = mat[std::size_t(i)];
        out.push_back(p);
      }
      if (seen.keep(cylinderMayBeSeen(mid, b, d.bond_radius))) {
        Primitive q = makeCylinder(mid, b, d.bond_radius);
        q.material = mat[std::size_t(j)];
        out.push_back(q);
      }
    }
  }
  return out;
}

std::vector<Primitive> buildPdb(const JsonNode& o, ObjectContext& ctx) {
  const JsonNode fileNode = o.at("file");
  const std::string path = fileNode.string();
  if (path.empty()) fileNode.fail("file name is empty");

  MoleculeDisplay d;
  const std::string style = o.string("style", "ball_and_stick");
  if (style == "ball_and_stick") {
    d.style = MoleculeStyle::BallAndStick;
    d.atom_scale = o.positive("atom_scale", 0.25);
    d.bond_radius = o.positive("bond_radius", 0.15);
  } else if (style == "spacefill") {
    d.style = MoleculeStyle::Spacefill;
    d.atom_scale = o.positive("atom_scale", 1.0);
    if (auto b = o.get("bond_radius")) b->fail("bond_radius applies to the ball_and_stick style only");
  } else {
    o.at("style").fail("unknown style '" + style + "' (expected spacefill or ball_and_stick)");
  }
  const bool center = o.boolean("center", false);
  const bool waters = o.boolean("waters", true);

  Molecule mol;
  try {
    mol = readPdb(ctx.resolve(path), ctx.limits.max_input_bytes);
  } catch (const std::runtime_error& e) {
    fileNode.fail(e.what());
  }
  if (mol.atoms.empty()) fileNode.fail("no ATOM/HETATM records in " + path);
  if (!waters) {
    std::vector<Atom> kept;
    for (const auto& a : mol.atoms)
      if (a.residue != "HOH" && a.residue != "WAT" && a.residue != "DOD") kept.push_back(a);
    mol.atoms = std::move(kept);
    mol.bonds = inferBonds(mol.atoms);
    if (mol.atoms.empty()) o.at("waters").fail("every atom of " + path + " belongs to a water molecule");
  }
  if (center) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& a : mol.atoms) c += a.position;
    c /= double(mol.atoms.size());
    for (auto& a : mol.atoms) a.position -= c;
  }

  auto materialOf = [&ctx](const std::string& element) -> int {
    if (ctx.has_material) return ctx.material;
    const std::string name = "pdb:" + element;
    for (std::size_t k = 0; k < ctx.scene.materials.size(); ++k)
      if (ctx.scene.materials[k].name == name) return int(k);
    Material m;
    m.name = name;
    const Eigen::Vector3d s = cpkColor(element);
    m.color = {srgbToLinear(s.x()), srgbToLinear(s.y()), srgbToLinear(s.z())};
    m.specular = 0.3;
    m.shininess = 32;
    ctx.scene.materials.push_back(m);
    return int(ctx.scene.materials.size() - 1);
  };
  ViewCullCount seen(ctx.view != nullptr);
  std::vector<Primitive> prims = moleculePrimitives(mol, d, materialOf, ctx.view, &seen);
  ctx.note = seen.note();
  return prims;
}

namespace {
// The scene object type this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"pdb", buildPdb},
});

}  // namespace

}  // namespace qacc
