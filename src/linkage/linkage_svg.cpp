#include "reconfig/linkage/linkage_svg.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "reconfig/common/input_error.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::linkage {
namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", value);
  return buffer;
}

}  // namespace

std::string linkage_svg(const Linkage& linkage, const SvgOptions& options) {
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const MotionRange range = motion_range(kinematics);
  const int n = static_cast<int>(linkage.joints.size());
  const int samples = std::max(2, options.samples);
  std::vector<Eigen::Matrix2Xd> frames;
  Eigen::Matrix2Xd X;
  ReconstructionFailure failure;
  for (int s = 0; s < samples; ++s) {
    const double t = range.full_rotation ? static_cast<double>(s) / samples : static_cast<double>(s) / (samples - 1);
    if (!kinematics.solve(range.lower + t * (range.upper - range.lower), X, &failure))
      throw InputError("", "", failure.message);
    frames.push_back(X);
  }
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  Eigen::Vector2d lo = X0.rowwise().minCoeff(), hi = X0.rowwise().maxCoeff();
  for (const auto& frame : frames) lo = lo.cwiseMin(frame.rowwise().minCoeff()), hi = hi.cwiseMax(frame.rowwise().maxCoeff());
  const double extent = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-9});
  lo.array() -= 0.05 * extent, hi.array() += 0.05 * extent;
  const double header = options.title.empty() ? 24 : 44;
  const double scale = options.width / (hi.x() - lo.x());
  const double height = (hi.y() - lo.y()) * scale + header;
  auto px = [&](const Eigen::Vector2d& p) { return number((p.x() - lo.x()) * scale) + "," + number((hi.y() - p.y()) * scale + header); };

  std::vector<bool> tracked(n, false);
  for (const auto& point : linkage.tracking_points) tracked[point.joint] = true;
  static const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"};

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(options.width) << "\" height=\""
      << number(height) << "\" viewBox=\"0 0 " << number(options.width) << " " << number(height) << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!options.title.empty())
    svg << "<text x=\"8\" y=\"20\" font-family=\"sans-serif\" font-size=\"16\">" << escape(options.title) << "</text>\n";
  svg << "<text x=\"8\" y=\"" << number(header - 6) << "\" font-family=\"sans-serif\" font-size=\"12\" fill=\"#555\">"
      << escape(range.full_rotation ? "full rotation" : range.describe().substr(0, range.describe().find(" (")))
      << "</text>\n";
  svg << "<g id=\"curves\" fill=\"none\">\n";
  int color = 0;
  for (int k = 0; k < n; ++k) {
    if (linkage.joints[k].fixed) continue;
    svg << "<" << (range.full_rotation ? "polygon" : "polyline") << " data-joint=\"" << escape(linkage.joints[k].name)
        << "\" points=\"";
    for (const auto& frame : frames) svg << px(frame.col(k)) << " ";
    if (tracked[k]) svg << "\" stroke=\"" << kColors[color++ % 6] << "\" stroke-width=\"2\"/>\n";
    else svg << "\" stroke=\"#bbb\" stroke-width=\"1\"/>\n";
  }
  svg << "</g>\n<g id=\"links\">\n";
  for (const auto& link : linkage.links) {
    if (link.size() == 2) {
      svg << "<line x1=\"" << number((X0(0, link[0]) - lo.x()) * scale) << "\" y1=\""
          << number((hi.y() - X0(1, link[0])) * scale + header) << "\" x2=\"" << number((X0(0, link[1]) - lo.x()) * scale)
          << "\" y2=\"" << number((hi.y() - X0(1, link[1])) * scale + header)
          << "\" stroke=\"#333\" stroke-width=\"3\" stroke-linecap=\"round\"/>\n";
    } else {
      svg << "<polygon points=\"";
      for (int j : link) svg << px(X0.col(j)) << " ";
      svg << "\" fill=\"#4a90d9\" fill-opacity=\"0.25\" stroke=\"#333\" stroke-width=\"2\" stroke-linejoin=\"round\"/>\n";
    }
  }
  svg << "</g>\n<g id=\"joints\">\n";
  for (int k = 0; k < n; ++k) {
    const double x = (X0(0, k) - lo.x()) * scale, y = (hi.y() - X0(1, k)) * scale + header;
    if (linkage.joints[k].fixed)
      svg << "<rect x=\"" << number(x - 5) << "\" y=\"" << number(y - 5)
          << "\" width=\"10\" height=\"10\" fill=\"#222\"/>\n";
    else
      svg << "<circle cx=\"" << number(x) << "\" cy=\"" << number(y) << "\" r=\"4\" fill=\""
          << (k == linkage.motor.joint ? "#d62728" : "white") << "\" stroke=\"#222\" stroke-width=\"1.5\"/>\n";
    svg << "<text x=\"" << number(x + 6) << "\" y=\"" << number(y - 6)
        << "\" font-family=\"sans-serif\" font-size=\"10\" fill=\"#444\">" << escape(linkage.joints[k].name) << "</text>\n";
  }
  svg << "</g>\n</svg>\n";
  return svg.str();
}

}  // namespace reconfig::linkage
