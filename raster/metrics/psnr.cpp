#include "raster/metrics/psnr.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace qacc {

double meanSquaredError(const Image8& a, const Image8& b) {
  if (!a.sameShape(b)) throw std::invalid_argument("meanSquaredError: images differ in shape");
  if (a.data.empty()) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    const double d = double(a.data[i]) - double(b.data[i]);
    sum += d * d;
  }
  return sum / double(a.data.size());
}

double psnr(const Image8& a, const Image8& b) {
  const double mse = meanSquaredError(a, b);
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace qacc
