// A small log–log scatter plot written as SVG text: a grid of panels, points coloured by one
// category and shaped by another, filled or hollow by a third (the series), a polyline per series
// and panel (its Pareto front) and an optional dashed horizontal line (a floor). Output only: no
// GUI toolkit, no dependency.
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
  int series = 0;  // index into PlotSpec::series: how the point is painted and whose front it is on
  bool faded = false;
  std::string tooltip;
};

struct PlotFront {
  int series = 0;
  std::vector<std::pair<double, double>> points;  // polyline through these (x, y), in order
};

struct PlotPanel {
  std::string title;
  std::vector<PlotPoint> points;
  std::vector<PlotFront> fronts;
  std::optional<double> floor;  // dashed horizontal line at this y
};

// A set of points told apart from the others by their paint, with its own front: filled or hollow
// markers, the front's colour and dash pattern (SVG stroke-dasharray; empty: solid).
struct PlotSeries {
  std::string label;
  bool hollow = false;
  std::string front_color = "black";
  std::string front_dash;
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
  // One series (the default) needs no legend line; more get one, with their fronts.
  std::vector<PlotSeries> series{PlotSeries{}};
  std::string series_title;
  std::string front_label = "Pareto front";
  std::string floor_label = "reference's own error";
  std::string faded_label;  // legend text for faded markers; empty: no entry
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
