// Robust real-root isolation of a univariate polynomial on [0, 1] by Bernstein
// subdivision (no fixed-step marching): the Bernstein coefficients bound the polynomial
// (convex hull), their sign variations bound its number of roots (Descartes' rule for the
// Bernstein basis), and de Casteljau halving is numerically stable.
//
// Tolerances (the contract the tests check):
//  - a coefficient with |b| <= zero_tol x max|b| counts as zero (zero_tol = 1e-12 by
//    default), so a tangency (double root, e.g. a ray grazing a silhouette) is found where
//    the polynomial comes within that relative tolerance of zero: its parameter is exact to
//    about sqrt(zero_tol) (1e-6 of the interval), and a ray that misses the surface by a
//    relative distance below ~1e-6 may report such a grazing hit;
//  - a simple root isolated by one strict sign change is bisected to 1e-14; in general a
//    simple root r is found within zero_tol x max|b| / |f'(r)| (its conditioning: e.g.
//    2.5e-9 for the pair 0.5, 0.5001 of (t - 0.5)(t - 0.5001)).
#pragma once
#include <vector>

namespace qacc {

// Power coefficients a_0..a_n of Σ a_m t^m → Bernstein coefficients on [0, 1].
std::vector<double> powerToBernstein(const std::vector<double>& a);
// Value of a Bernstein polynomial on [0, 1] at s (de Casteljau).
double evalBernstein(const std::vector<double>& b, double s);

struct RootOptions {
  double zero_tol = 1e-12;   // relative to max |b|
  double min_width = 1e-13;  // interval width where an ambiguous interval is declared a root
};

// Smallest root in [0, 1]; false if none (up to the tolerances above).
bool firstBernsteinRoot(const std::vector<double>& b, double& root, const RootOptions& opt = {});
// All roots in [0, 1], increasing; a root of multiplicity > 1 is reported once (clusters
// closer than 1e-5 are merged).
std::vector<double> allBernsteinRoots(const std::vector<double>& b, const RootOptions& opt = {});

}  // namespace qacc
