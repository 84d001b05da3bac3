// Small SVG line plots for the compare/sweep reports (no plotting dependency): a grid of
// panels, each with a log or linear x axis, one or more series of points and optional
// horizontal reference lines (e.g. the accelerator's error).
#pragma once
#include <string>
#include <vector>

namespace qacc {

struct PlotSeries {
  std::string label;
  std::string color = "#1f77b4";
  std::vector<double> x, y;  // non-finite points are skipped
};

struct PlotLine {  // horizontal reference line
  std::string label;
  std::string color = "#d62728";
  double y = 0;
};

struct PlotPanel {
  std::string title;
  std::string xlabel, ylabel;
  bool log_x = true;
  bool log_y = false;
  std::vector<PlotSeries> series;
  std::vector<PlotLine> lines;
};

// Lays the panels out `columns` per row; returns the SVG document.
std::string svgPlot(const std::string& title, const std::vector<PlotPanel>& panels, int columns = 3);

}  // namespace qacc
