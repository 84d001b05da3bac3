#include "tools/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace qacc {

namespace {

std::string esc(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

std::string num(double v) {
  char b[32];
  if (v != 0 && (std::abs(v) >= 1e5 || std::abs(v) < 1e-3)) std::snprintf(b, sizeof b, "%.2g", v);
  else std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

std::string svgPlot(const std::string& title, const std::vector<PlotPanel>& panels, int columns) {
  const int pw = 360, ph = 260, ml = 62, mr = 12, mt = 28, mb = 44;
  const int cols = std::max(1, std::min(columns, int(panels.size())));
  const int rows = int((panels.size() + std::size_t(cols) - 1) / std::size_t(cols));
  const int W = cols * pw, H = rows * ph + 36;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << esc(title) << "</text>\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const PlotPanel& P = panels[p];
    const int ox = int(p % std::size_t(cols)) * pw, oy = 36 + int(p / std::size_t(cols)) * ph;
    const int x0 = ox + ml, x1 = ox + pw - mr, y0 = oy + ph - mb, y1 = oy + mt;
    auto tx = [&](double v) { return P.log_x ? std::log10(v) : v; };
    auto ty = [&](double v) { return P.log_y ? std::log10(v) : v; };
    auto ok = [&](double x, double y) {
      return std::isfinite(x) && std::isfinite(y) && (!P.log_x || x > 0) && (!P.log_y || y > 0);
    };
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const auto& s : P.series)
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
        if (ok(s.x[i], s.y[i])) {
          xmin = std::min(xmin, tx(s.x[i]));
          xmax = std::max(xmax, tx(s.x[i]));
          ymin = std::min(ymin, ty(s.y[i]));
          ymax = std::max(ymax, ty(s.y[i]));
        }
    for (const auto& l : P.lines)
      if (std::isfinite(l.y) && (!P.log_y || l.y > 0)) {
        ymin = std::min(ymin, ty(l.y));
        ymax = std::max(ymax, ty(l.y));
      }
    o << "<text x=\"" << (x0 + x1) / 2 << "\" y=\"" << oy + 16 << "\" text-anchor=\"middle\" font-size=\"12\">"
      << esc(P.title) << "</text>\n";
    o << "<rect x=\"" << x0 << "\" y=\"" << y1 << "\" width=\"" << x1 - x0 << "\" height=\"" << y0 - y1
      << "\" fill=\"none\" stroke=\"#888\"/>\n";
    if (!(xmin <= xmax) || !(ymin <= ymax)) {
      o << "<text x=\"" << (x0 + x1) / 2 << "\" y=\"" << (y0 + y1) / 2 << "\" text-anchor=\"middle\">no finite data</text>\n";
      continue;
    }
    if (xmax - xmin < 1e-12) { xmin -= 0.5; xmax += 0.5; }
    if (ymax - ymin < 1e-12) { ymin -= 0.5 * (std::abs(ymin) + 1); ymax += 0.5 * (std::abs(ymax) + 1); }
    const double padY = 0.06 * (ymax - ymin);
    ymin -= padY;
    ymax += padY;
    auto X = [&](double v) { return x0 + (tx(v) - xmin) / (xmax - xmin) * (x1 - x0); };
    auto Y = [&](double v) { return y0 - (ty(v) - ymin) / (ymax - ymin) * (y0 - y1); };
    // Ticks: 5 along each axis (powers of ten when logarithmic and the range allows).
    for (int i = 0; i <= 4; ++i) {
      const double fx = xmin + (xmax - xmin) * i / 4.0, fy = ymin + (ymax - ymin) * i / 4.0;
      const double vx = P.log_x ? std::pow(10.0, fx) : fx, vy = P.log_y ? std::pow(10.0, fy) : fy;
      const double px = x0 + (x1 - x0) * i / 4.0, py = y0 - (y0 - y1) * i / 4.0;
      o << "<line x1=\"" << px << "\" y1=\"" << y0 << "\" x2=\"" << px << "\" y2=\"" << y1
        << "\" stroke=\"#eee\"/><text x=\"" << px << "\" y=\"" << y0 + 14 << "\" text-anchor=\"middle\">" << num(vx)
        << "</text>\n";
      o << "<line x1=\"" << x0 << "\" y1=\"" << py << "\" x2=\"" << x1 << "\" y2=\"" << py
        << "\" stroke=\"#eee\"/><text x=\"" << x0 - 4 << "\" y=\"" << py + 4 << "\" text-anchor=\"end\">" << num(vy)
        << "</text>\n";
    }
    o << "<text x=\"" << (x0 + x1) / 2 << "\" y=\"" << y0 + 32 << "\" text-anchor=\"middle\">" << esc(P.xlabel)
      << (P.log_x ? " (log)" : "") << "</text>\n";
    o << "<text transform=\"translate(" << ox + 14 << "," << (y0 + y1) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
      << esc(P.ylabel) << "</text>\n";
    int legend = 0;
    for (const auto& l : P.lines) {
      if (!std::isfinite(l.y) || (P.log_y && l.y <= 0)) continue;
      o << "<line x1=\"" << x0 << "\" y1=\"" << Y(l.y) << "\" x2=\"" << x1 << "\" y2=\"" << Y(l.y) << "\" stroke=\""
        << l.color << "\" stroke-dasharray=\"6,4\" stroke-width=\"1.5\"/>\n";
      o << "<text x=\"" << x1 - 4 << "\" y=\"" << y1 + 14 + 13 * legend++ << "\" text-anchor=\"end\" fill=\"" << l.color
        << "\">" << esc(l.label) << "</text>\n";
    }
    for (const auto& s : P.series) {
      std::ostringstream path;
      bool first = true;
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
        if (!ok(s.x[i], s.y[i])) continue;
        path << (first ? "M" : " L") << X(s.x[i]) << "," << Y(s.y[i]);
        o << "<circle cx=\"" << X(s.x[i]) << "\" cy=\"" << Y(s.y[i]) << "\" r=\"3\" fill=\"" << s.color << "\"/>\n";
        first = false;
      }
      if (!first)
        o << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"1.5\"/>\n";
      o << "<text x=\"" << x1 - 4 << "\" y=\"" << y1 + 14 + 13 * legend++ << "\" text-anchor=\"end\" fill=\"" << s.color
        << "\">" << esc(s.label) << "</text>\n";
    }
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace qacc
