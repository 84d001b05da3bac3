// Trivariate polynomial of any degree, f(x, y, z) = Σ a_ijk x^i y^j z^k (digest §4: the
// algebraic surfaces f = 0 that degree reduction approximates by quadric pieces).
//
// Parsed from text such as "x^4 + y^4 + z^4 - 1" or
// "(x^2+y^2+z^2+R^2-r^2)^2 - 4 R^2 (x^2+y^2)": numbers, the variables x y z, named
// constants (given by the caller, e.g. from a scene's "params"), + - * ^ (non-negative
// integer exponents), parentheses, unary signs, and implicit multiplication by
// juxtaposition ("4 R^2 (x^2+y^2)", "2x"; a number only leads a product, so "x^2.5" is an
// error, not x^2 * .5). Errors name the character position.
#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace qacc {

struct PolynomialParseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Polynomial3 {
 public:
  struct Term {
    int i = 0, j = 0, k = 0;  // exponents of x, y, z
    double a = 0;             // coefficient
  };

  Polynomial3() = default;
  static Polynomial3 constant(double c);
  static Polynomial3 variable(int axis);  // 0 = x, 1 = y, 2 = z
  static Polynomial3 monomial(int i, int j, int k, double a);
  // Affine form a·p + d.
  static Polynomial3 affine(const Eigen::Vector3d& a, double d);
  // Parsed text never expands beyond this total degree (products and powers are checked
  // before they are expanded), so a short text cannot expand into millions of terms.
  static constexpr int kMaxParsedDegree = 64;
  // ... nor multiplies more than this many pairs of terms in one product (about 0.3 s).
  static constexpr long long kMaxParsedTermProducts = 4'000'000;
  // Throws PolynomialParseError with the position and the problem.
  static Polynomial3 parse(const std::string& text, const std::map<std::string, double>& constants = {});

  // Terms with non-zero coefficients, sorted by (i, j, k); an exact zero polynomial has none.
  const std::vector<Term>& terms() const { return terms_; }
  int degree() const;  // total degree (0 for constants and for the zero polynomial)
  double coefficient(int i, int j, int k) const;
  bool isZero() const { return terms_.empty(); }

  double eval(const Eigen::Vector3d& p) const;
  Eigen::Vector3d gradient(const Eigen::Vector3d& p) const;
  // ∂f/∂axis as a polynomial.
  Polynomial3 derivative(int axis) const;

  // Restriction to the line p(t) = p0 + t d: coefficients c_0..c_n of Σ c_m t^m (n = degree()).
  std::vector<double> alongLine(const Eigen::Vector3d& p0, const Eigen::Vector3d& d) const;

  Polynomial3 operator+(const Polynomial3& o) const;
  Polynomial3 operator-(const Polynomial3& o) const;
  Polynomial3 operator*(const Polynomial3& o) const;
  Polynomial3 operator*(double s) const;
  Polynomial3 operator-() const { return *this * -1.0; }
  Polynomial3 pow(int e) const;

  // Human-readable form, e.g. "x^4 + y^4 + z^4 - 1".
  std::string toString() const;

 private:
  std::vector<Term> terms_;
  void normalize();  // sort, merge equal exponents, drop exact zeros
};

}  // namespace qacc
