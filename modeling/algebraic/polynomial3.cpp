#include "modeling/algebraic/polynomial3.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <tuple>

namespace qacc {

Polynomial3 Polynomial3::constant(double c) { return monomial(0, 0, 0, c); }

Polynomial3 Polynomial3::variable(int axis) {
  return monomial(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0, 1.0);
}

Polynomial3 Polynomial3::monomial(int i, int j, int k, double a) {
  Polynomial3 p;
  if (a != 0.0) p.terms_.push_back({i, j, k, a});
  return p;
}

Polynomial3 Polynomial3::affine(const Eigen::Vector3d& a, double d) {
  Polynomial3 p;
  p.terms_ = {{0, 0, 0, d}, {1, 0, 0, a.x()}, {0, 1, 0, a.y()}, {0, 0, 1, a.z()}};
  p.normalize();
  return p;
}

void Polynomial3::normalize() {
  std::sort(terms_.begin(), terms_.end(), [](const Term& u, const Term& v) {
    return std::tie(u.i, u.j, u.k) < std::tie(v.i, v.j, v.k);
  });
  std::vector<Term> out;
  for (const Term& t : terms_) {
    if (!out.empty() && out.back().i == t.i && out.back().j == t.j && out.back().k == t.k)
      out.back().a += t.a;
    else
      out.push_back(t);
  }
  out.erase(std::remove_if(out.begin(), out.end(), [](const Term& t) { return t.a == 0.0; }), out.end());
  terms_ = std::move(out);
}

int Polynomial3::degree() const {
  int d = 0;
  for (const Term& t : terms_) d = std::max(d, t.i + t.j + t.k);
  return d;
}

double Polynomial3::coefficient(int i, int j, int k) const {
  for (const Term& t : terms_)
    if (t.i == i && t.j == j && t.k == k) return t.a;
  return 0.0;
}

namespace {
// Powers v^0..v^n.
void powers(double v, int n, std::vector<double>& out) {
  out.resize(std::size_t(n) + 1);
  out[0] = 1.0;
  for (int m = 1; m <= n; ++m) out[std::size_t(m)] = out[std::size_t(m) - 1] * v;
}
}  // namespace

double Polynomial3::eval(const Eigen::Vector3d& p) const {
  const int n = degree();
  thread_local std::vector<double> px, py, pz;
  powers(p.x(), n, px);
  powers(p.y(), n, py);
  powers(p.z(), n, pz);
  double s = 0.0;
  for (const Term& t : terms_) s += t.a * px[std::size_t(t.i)] * py[std::size_t(t.j)] * pz[std::size_t(t.k)];
  return s;
}

Eigen::Vector3d Polynomial3::gradient(const Eigen::Vector3d& p) const {
  const int n = degree();
  thread_local std::vector<double> px, py, pz;
  powers(p.x(), n, px);
  powers(p.y(), n, py);
  powers(p.z(), n, pz);
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (const Term& t : terms_) {
    const std::size_t i = std::size_t(t.i), j = std::size_t(t.j), k = std::size_t(t.k);
    if (t.i > 0) g.x() += t.a * t.i * px[i - 1] * py[j] * pz[k];
    if (t.j > 0) g.y() += t.a * t.j * px[i] * py[j - 1] * pz[k];
    if (t.k > 0) g.z() += t.a * t.k * px[i] * py[j] * pz[k - 1];
  }
  return g;
}

Polynomial3 Polynomial3::derivative(int axis) const {
  Polynomial3 d;
  for (const Term& t : terms_) {
    const int e = axis == 0 ? t.i : axis == 1 ? t.j : t.k;
    if (e == 0) continue;
    Term u = t;
    u.a *= e;
    (axis == 0 ? u.i : axis == 1 ? u.j : u.k) -= 1;
    d.terms_.push_back(u);
  }
  d.normalize();
  return d;
}

std::vector<double> Polynomial3::alongLine(const Eigen::Vector3d& p0, const Eigen::Vector3d& d) const {
  const int n = degree();
  // pw[axis][e] = (p0_axis + t d_axis)^e as coefficients in t (binomial expansion).
  std::vector<std::vector<double>> pw[3];
  for (int a = 0; a < 3; ++a) {
    pw[a].resize(std::size_t(n) + 1);
    pw[a][0] = {1.0};
    for (int e = 1; e <= n; ++e) {
      const auto& prev = pw[a][std::size_t(e) - 1];
      std::vector<double> cur(std::size_t(e) + 1, 0.0);
      for (std::size_t m = 0; m < prev.size(); ++m) {
        cur[m] += prev[m] * p0[a];
        cur[m + 1] += prev[m] * d[a];
      }
      pw[a][std::size_t(e)] = std::move(cur);
    }
  }
  std::vector<double> c(std::size_t(n) + 1, 0.0), xy;
  for (const Term& t : terms_) {
    const auto& X = pw[0][std::size_t(t.i)];
    const auto& Y = pw[1][std::size_t(t.j)];
    const auto& Z = pw[2][std::size_t(t.k)];
    xy.assign(X.size() + Y.size() - 1, 0.0);
    for (std::size_t u = 0; u < X.size(); ++u)
      for (std::size_t v = 0; v < Y.size(); ++v) xy[u + v] += X[u] * Y[v];
    for (std::size_t u = 0; u < xy.size(); ++u)
      for (std::size_t v = 0; v < Z.size(); ++v) c[u + v] += t.a * xy[u] * Z[v];
  }
  return c;
}

Polynomial3 Polynomial3::operator+(const Polynomial3& o) const {
  Polynomial3 r = *this;
  r.terms_.insert(r.terms_.end(), o.terms_.begin(), o.terms_.end());
  r.normalize();
  return r;
}

Polynomial3 Polynomial3::operator-(const Polynomial3& o) const { return *this + o * -1.0; }

Polynomial3 Polynomial3::operator*(const Polynomial3& o) const {
  Polynomial3 r;
  r.terms_.reserve(terms_.size() * o.terms_.size());
  for (const Term& u : terms_)
    for (const Term& v : o.terms_) r.terms_.push_back({u.i + v.i, u.j + v.j, u.k + v.k, u.a * v.a});
  r.normalize();
  return r;
}

Polynomial3 Polynomial3::operator*(double s) const {
  Polynomial3 r = *this;
  for (Term& t : r.terms_) t.a *= s;
  r.normalize();
  return r;
}

Polynomial3 Polynomial3::pow(int e) const {
  if (e < 0) throw std::invalid_argument("Polynomial3::pow: negative exponent");
  Polynomial3 r = constant(1.0), b = *this;
  while (e > 0) {
    if (e & 1) r = r * b;
    e >>= 1;
    if (e) b = b * b;
  }
  return r;
}

std::string Polynomial3::toString() const {
  if (terms_.empty()) return "0";
  // Highest degree first, then x before y before z.
  std::vector<Term> t = terms_;
  std::stable_sort(t.begin(), t.end(), [](const Term& u, const Term& v) {
    const int du = u.i + u.j + u.k, dv = v.i + v.j + v.k;
    if (du != dv) return du > dv;
    return std::tie(v.i, v.j, v.k) < std::tie(u.i, u.j, u.k);
  });
  std::ostringstream s;
  s.precision(12);
  bool first = true;
  for (const Term& u : t) {
    double a = u.a;
    if (first) {
      if (a < 0) s << "-";
    } else {
      s << (a < 0 ? " - " : " + ");
    }
    a = std::fabs(a);
    const bool pure = u.i + u.j + u.k == 0;
    bool wrote = false;
    if (pure || a != 1.0) {
      s << a;
      wrote = true;
    }
    const char* names = "xyz";
    const int e[3] = {u.i, u.j, u.k};
    for (int v = 0; v < 3; ++v) {
      if (e[v] == 0) continue;
      if (wrote) s << " ";
      s << names[v];
      if (e[v] > 1) s << "^" << e[v];
      wrote = true;
    }
    first = false;
  }
  return s.str();
}

// ---- Parser: recursive descent over the text. ----
namespace {

class Parser {
 public:
  Parser(const std::string& text, const std::map<std::string, double>& constants)
      : s_(text), constants_(constants) {}
  static constexpr int kMaxDegree = Polynomial3::kMaxParsedDegree;

  Polynomial3 parse() {
    skip();
    if (pos_ >= s_.size()) fail("empty polynomial");
    Polynomial3 p = expr();
    skip();
    if (pos_ < s_.size()) fail(std::string("unexpected '") + s_[pos_] + "'");
    return p;
  }

 private:
  const std::string& s_;
  const std::map<std::string, double>& constants_;
  std::size_t pos_ = 0;
  int depth_ = 0;

  [[noreturn]] void fail(const std::string& what) const {
    throw PolynomialParseError("polynomial \"" + s_ + "\", position " + std::to_string(pos_ + 1) + ": " + what);
  }
  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool peek(char c) {
    skip();
    return pos_ < s_.size() && s_[pos_] == c;
  }
  bool startsPrimary() {
    skip();
    if (pos_ >= s_.size()) return false;
    const unsigned char c = static_cast<unsigned char>(s_[pos_]);
    // Numbers only lead a product ("2x", "4 R^2"): "x^2.5" or "x 2" are errors, not products.
    return std::isalpha(c) || c == '_' || c == '(';
  }

  Polynomial3 expr() {
    Polynomial3 p = term();
    for (;;) {
      if (peek('+')) {
        ++pos_;
        p = p + term();
      } else if (peek('-')) {
        ++pos_;
        p = p - term();
      } else {
        return p;
      }
    }
  }

  Polynomial3 term() {
    Polynomial3 p = factor();
    for (;;) {
      if (peek('*')) {
        ++pos_;
        p = times(p, factor());
      } else if (startsPrimary()) {
        p = times(p, factor());  // implicit multiplication: "4 R^2 (x^2+y^2)", "2x"
      } else {
        return p;
      }
    }
  }

  // Every product is checked before it is expanded, on its degree and on the number of term
  // products it costs: "(x+y+z)^64 (x+y+z)^64 ..." would otherwise grow without bound (a
  // degree-d polynomial has up to (d+1)(d+2)(d+3)/6 terms; squaring 6545 terms costs 43 M).
  Polynomial3 times(const Polynomial3& a, const Polynomial3& b) const {
    if (a.degree() + b.degree() > kMaxDegree)
      fail("the expanded degree exceeds " + std::to_string(kMaxDegree));
    const double cost = double(a.terms().size()) * double(b.terms().size());
    if (cost > double(Polynomial3::kMaxParsedTermProducts))
      fail("expanding a product needs " + std::to_string((long long)cost) + " term products, above the supported " +
           std::to_string(Polynomial3::kMaxParsedTermProducts));
    return a * b;
  }
  Polynomial3 power(Polynomial3 b, int e) const {
    Polynomial3 r = Polynomial3::constant(1.0);
    while (e > 0) {
      if (e & 1) r = times(r, b);
      e >>= 1;
      if (e) b = times(b, b);
    }
    return r;
  }

  Polynomial3 factor() {
    // Unary signs are counted in a loop, not by recursion: a string of 40 000 '-' signs must
    // not overflow the stack.
    bool negative = false;
    for (;;) {
      if (peek('-')) {
        ++pos_;
        negative = !negative;
      } else if (peek('+')) {
        ++pos_;
      } else {
        break;
      }
    }
    Polynomial3 f = powerExpr();
    return negative ? -f : f;
  }

  Polynomial3 powerExpr() {
    Polynomial3 b = primary();
    if (peek('^')) {
      ++pos_;
      skip();
      const std::size_t start = pos_;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
      if (start == pos_) fail("expected a non-negative integer exponent after '^'");
      const std::string digits = s_.substr(start, pos_ - start);
      if (digits.size() > 3 || std::stoi(digits) > kMaxDegree)
        fail("exponent " + digits + " is too large (at most " + std::to_string(kMaxDegree) + ")");
      const int e = std::stoi(digits);
      if (b.degree() * e > kMaxDegree) fail("the expanded degree exceeds " + std::to_string(kMaxDegree));
      return power(b, e);
    }
    return b;
  }

  Polynomial3 primary() {
    skip();
    if (pos_ >= s_.size()) fail("unexpected end of polynomial");
    const unsigned char c = static_cast<unsigned char>(s_[pos_]);
    if (c == '(') {
      if (++depth_ > 200) fail("parentheses nested too deeply");
      ++pos_;
      Polynomial3 p = expr();
      if (!peek(')')) fail("expected ')'");
      ++pos_;
      --depth_;
      return p;
    }
    if (std::isdigit(c) || c == '.') {
      // digits [. digits] [(e|E) [+|-] digits]; scanned by hand so that "0x" is 0 times x.
      const std::size_t start = pos_;
      auto digit = [&](std::size_t i) {
        return i < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i]));
      };
      while (digit(pos_)) ++pos_;
      if (pos_ < s_.size() && s_[pos_] == '.') ++pos_;
      while (digit(pos_)) ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
        std::size_t q = pos_ + 1;
        if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
        if (digit(q)) {
          pos_ = q;
          while (digit(pos_)) ++pos_;
        }
      }
      const std::string lit = s_.substr(start, pos_ - start);
      if (lit == ".") {
        pos_ = start;
        fail("malformed number");
      }
      const double v = std::strtod(lit.c_str(), nullptr);
      if (!std::isfinite(v)) {
        pos_ = start;
        fail("number out of range");
      }
      return Polynomial3::constant(v);
    }
    if (std::isalpha(c) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < s_.size() &&
             (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
        ++pos_;
      const std::string name = s_.substr(start, pos_ - start);
      if (name == "x") return Polynomial3::variable(0);
      if (name == "y") return Polynomial3::variable(1);
      if (name == "z") return Polynomial3::variable(2);
      auto it = constants_.find(name);
      if (it != constants_.end()) return Polynomial3::constant(it->second);
      pos_ = start;
      fail("unknown name '" + name + "' (variables are x, y, z; write products as x*y; other names must be given in \"params\")");
    }
    fail(std::string("unexpected '") + s_[pos_] + "'");
  }
};

}  // namespace

Polynomial3 Polynomial3::parse(const std::string& text, const std::map<std::string, double>& constants) {
  return Parser(text, constants).parse();
}

}  // namespace qacc
