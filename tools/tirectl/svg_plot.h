// A small log–log scatter plot written as SVG text: a grid of panels, points coloured by one
// category and shaped by another, a polyline per panel (the Pareto front) and an optional dashed
// horizontal line (a floor). Output only: no GUI toolkit, no dependency.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tirectl {

struct PlotPoint {
  double x = 0.0;  // > 0
  double y = 0.0;  // > 0 (values at or below zero are drawn at the bottom of the axis)
  int color = 0;   // index into PlotSpec::colors
  int marker = 0;  // index into PlotSpec::markers: circle, square, triangle, diamond, down-triangle, star
  bool hollow = false;
  std::string tooltip;
};

struct PlotPanel {
  std::string title;
  std::vector<PlotPoint> points;
  std::vector<std::pair<double, double>> front;  // polyline through these (x, y), in order
  std::optional<double> floor;                   // dashed horizontal line at this y
};

struct PlotLegendEntry {
  std::string label;
};

struct PlotSpec {
  std::string title;
  std::string subtitle;
  std::string x_label;
  std::string y_label;
  int columns = 3;
  std::vector<PlotPanel> panels;  // row by row
  // Panels in one row share their y range (a row is one scenario); all share the x range.
  bool share_y_by_row = true;
  std::vector<std::string> colors;         // CSS colours, by PlotPoint::color
  std::vector<std::string> color_labels;   // legend text for each colour
  std::string color_title;                 // legend heading, e.g. "substeps"
  std::vector<std::string> marker_labels;  // legend text for each marker
  std::string marker_title;
  std::string front_label = "Pareto front";
  std::string floor_label = "reference's own error";
  std::string hollow_label;  // legend text for hollow markers; empty: no entry
  // Tick labels for the decade 10^e on each axis.
  std::function<std::string(int)> x_tick = nullptr;
  std::function<std::string(int)> y_tick = nullptr;
};

std::string render_svg(const PlotSpec& spec);

// Tick label helpers: "1 µs", "10 µs", "100 µs", "1 ms", ... and "1 µm", ..., "1 mm", "1 cm", "1 m".
std::string microseconds_label(int decade);
std::string metres_label(int decade);

// XML-escapes text for SVG.
std::string xml_escape(const std::string& text);

}  // namespace tirectl
