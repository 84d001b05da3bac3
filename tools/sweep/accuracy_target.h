// AccuracyTarget: "wrong<=0.1%,pinholes=0" — conditions on the accuracy columns of a sweep
// row, all of which must hold (`qacc autosize --target`, the "answer" of a sweep report).
// Names: wrong (percent of the pixels either image covers), wrong_object, pinholes,
// spurious, psnr (dB), ssim, hausdorff, silhouette_mean (px), depth_max, depth_mean (z24).
// Operators: <=, <, >=, >, =. A trailing % is allowed on wrong.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace qacc {

struct AccuracyCondition {
  std::string name;    // as written
  std::string column;  // the row column it reads
  std::string op;
  double value = 0;
  bool holds(double v) const;
};

struct AccuracyTarget {
  std::string text;
  std::vector<AccuracyCondition> conditions;
  bool empty() const { return conditions.empty(); }
  // Every condition holds on the row (a row without its columns, e.g. refused, fails).
  bool meets(const nlohmann::ordered_json& row) const;
};

// Throws std::invalid_argument naming the bad condition.
AccuracyTarget parseAccuracyTarget(const std::string& text);

}  // namespace qacc
