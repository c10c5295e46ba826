#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>

namespace tirectl {

namespace {

// Geometry (px).
constexpr double kPanelWidth = 360.0;
constexpr double kPanelHeight = 270.0;
constexpr double kPadLeft = 64.0;  // inside a panel, left of its axes: y tick labels
constexpr double kPadRight = 14.0;
constexpr double kPadTop = 26.0;     // panel title
constexpr double kPadBottom = 40.0;  // x tick labels and axis label
constexpr double kMargin = 16.0;
constexpr double kMarkerRadius = 4.5;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

struct Range {
  int lo = 0;  // decades
  int hi = 1;
};

struct Extent {
  double mn = std::numeric_limits<double>::infinity();
  double mx = 0.0;
  void add(double v) {
    if (!(v > 0.0) || !std::isfinite(v)) return;
    mn = std::min(mn, v);
    mx = std::max(mx, v);
  }
  Range decades() const {
    if (!(mx > 0.0)) return {0, 1};
    Range r{static_cast<int>(std::floor(std::log10(mn) + 1e-9)),
            static_cast<int>(std::ceil(std::log10(mx) - 1e-9))};
    if (r.hi <= r.lo) r.hi = r.lo + 1;
    return r;
  }
};

// Maps a value to a pixel along an axis from a to b (a at 10^lo).
double scale(double v, Range r, double a, double b) {
  const double lv = v > 0.0 ? std::log10(v) : static_cast<double>(r.lo);
  const double f =
      (std::clamp(lv, static_cast<double>(r.lo), static_cast<double>(r.hi)) - r.lo) / (r.hi - r.lo);
  return a + (b - a) * f;
}

// A hollow marker is drawn a little larger, with a thick outline, so that it still reads when it
// sits on a filled one of the same shape.
void marker(std::ostringstream& out, int kind, double x, double y, const std::string& color, bool hollow,
            bool faded = false, double r = kMarkerRadius) {
  if (hollow) r *= 1.2;
  std::string paint =
      hollow ? "fill=\"white\" fill-opacity=\"0.6\" stroke=\"" + color + "\" stroke-width=\"1.9\""
             : "fill=\"" + color + "\" stroke=\"" + color + "\" stroke-width=\"0.6\"";
  if (faded) paint += " opacity=\"0.4\"";
  switch (((kind % 6) + 6) % 6) {
    case 0:
      out << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"" << num(r) << "\" " << paint
          << "/>";
      break;
    case 1: {
      const double s = r * 0.9;
      out << "<rect x=\"" << num(x - s) << "\" y=\"" << num(y - s) << "\" width=\"" << num(2 * s)
          << "\" height=\"" << num(2 * s) << "\" " << paint << "/>";
      break;
    }
    case 2:
      out << "<polygon points=\"" << num(x) << "," << num(y - 1.2 * r) << " " << num(x + 1.1 * r) << ","
          << num(y + 0.8 * r) << " " << num(x - 1.1 * r) << "," << num(y + 0.8 * r) << "\" " << paint << "/>";
      break;
    case 3:
      out << "<polygon points=\"" << num(x) << "," << num(y - 1.25 * r) << " " << num(x + 1.25 * r) << ","
          << num(y) << " " << num(x) << "," << num(y + 1.25 * r) << " " << num(x - 1.25 * r) << "," << num(y)
          << "\" " << paint << "/>";
      break;
    case 4:
      out << "<polygon points=\"" << num(x) << "," << num(y + 1.2 * r) << " " << num(x + 1.1 * r) << ","
          << num(y - 0.8 * r) << " " << num(x - 1.1 * r) << "," << num(y - 0.8 * r) << "\" " << paint << "/>";
      break;
    default: {  // a five-pointed star
      out << "<polygon points=\"";
      for (int k = 0; k < 10; ++k) {
        const double a = -std::numbers::pi / 2 + k * std::numbers::pi / 5;
        const double rr = (k % 2 == 0 ? 1.35 : 0.6) * r;
        out << num(x + rr * std::cos(a)) << "," << num(y + rr * std::sin(a)) << " ";
      }
      out << "\" " << paint << "/>";
    }
  }
}

void ring(std::ostringstream& out, double x, double y, const std::string& color = "black") {
  out << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"" << num(kMarkerRadius + 2.5)
      << "\" fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\"/>";
}

// A front's line: its series' colour and dashes.
std::string front_stroke(const PlotSeries& s) {
  std::string a =
      "fill=\"none\" stroke=\"" + s.front_color + "\" stroke-width=\"1.6\" stroke-linejoin=\"round\"";
  if (!s.front_dash.empty()) a += " stroke-dasharray=\"" + s.front_dash + "\"";
  return a;
}

std::string superscript_power(int decade) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string s = "10";
  if (decade < 0) s += "⁻";
  const std::string d = std::to_string(std::abs(decade));
  for (const char c : d) s += digits[c - '0'];
  return s;
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string microseconds_label(int decade) {
  static const char* names[] = {"1 µs", "10 µs", "100 µs", "1 ms", "10 ms", "100 ms", "1 s"};
  if (decade >= 0 && decade <= 6) return names[decade];
  return superscript_power(decade) + " µs";
}

std::string metres_label(int decade) {
  switch (decade) {
    case -6: return "1 µm";
    case -5: return "10 µm";
    case -4: return "0.1 mm";
    case -3: return "1 mm";
    case -2: return "1 cm";
    case -1: return "10 cm";
    case 0: return "1 m";
    case 1: return "10 m";
    case 2: return "100 m";
    default: return superscript_power(decade) + " m";
  }
}

std::string render_svg(const PlotSpec& spec) {
  const int columns = std::max(1, spec.columns);
  const int rows = static_cast<int>((spec.panels.size() + static_cast<std::size_t>(columns) - 1) /
                                    static_cast<std::size_t>(columns));

  // Ranges: x shared by every panel, y by each row (or by all).
  Extent x_extent, all_y;
  std::vector<Extent> row_y(static_cast<std::size_t>(std::max(rows, 1)));
  for (std::size_t i = 0; i < spec.panels.size(); ++i) {
    const PlotPanel& p = spec.panels[i];
    Extent& ry = row_y[i / static_cast<std::size_t>(columns)];
    for (const PlotPoint& q : p.points) {
      x_extent.add(q.x);
      ry.add(q.y);
      all_y.add(q.y);
    }
    if (p.floor) ry.add(*p.floor), all_y.add(*p.floor);
  }
  const Range xr = x_extent.decades();

  const double legend_top =
      kMargin + (spec.subtitle.empty()
                     ? 34.0
                     : 37.0 + 17.0 * static_cast<double>(
                                         1 + std::count(spec.subtitle.begin(), spec.subtitle.end(), '\n')));
  const double legend_height = spec.series.size() > 1 ? 76.0 : 52.0;
  const double grid_top = legend_top + legend_height;
  const double width = 2 * kMargin + columns * kPanelWidth;
  const double height = grid_top + rows * kPanelHeight + kMargin;

  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(width) << " " << num(height)
      << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << num(width) << "\" height=\"" << num(height)
      << "\" fill=\"white\"/>\n";
  out << "<text x=\"" << num(kMargin) << "\" y=\"" << num(kMargin + 16)
      << "\" font-size=\"18\" font-weight=\"bold\">" << xml_escape(spec.title) << "</text>\n";
  // The subtitle, one line per '\n'.
  int subtitle_lines = 0;
  for (std::size_t begin = 0; begin <= spec.subtitle.size() && !spec.subtitle.empty(); ++subtitle_lines) {
    const std::size_t end = std::min(spec.subtitle.find('\n', begin), spec.subtitle.size());
    out << "<text x=\"" << num(kMargin) << "\" y=\"" << num(kMargin + 38 + 17 * subtitle_lines)
        << "\" font-size=\"12.5\" fill=\"#444\">" << xml_escape(spec.subtitle.substr(begin, end - begin))
        << "</text>\n";
    begin = end + 1;
  }

  // Legend: colours on the first line, markers and lines on the second.
  {
    double x = kMargin;
    double y = legend_top + 14;
    out << "<g font-size=\"12\">\n";
    out << "<text x=\"" << num(x) << "\" y=\"" << num(y + 4) << "\" font-weight=\"bold\">"
        << xml_escape(spec.color_title) << "</text>\n";
    x += 8.0 * static_cast<double>(spec.color_title.size()) + 14;
    for (std::size_t i = 0; i < spec.colors.size() && i < spec.color_labels.size(); ++i) {
      marker(out, 0, x, y, spec.colors[i], false);
      out << "<text x=\"" << num(x + 9) << "\" y=\"" << num(y + 4) << "\">"
          << xml_escape(spec.color_labels[i]) << "</text>\n";
      x += 18 + 7.5 * static_cast<double>(spec.color_labels[i].size()) + 10;
    }
    x = kMargin;
    y += 24;
    out << "<text x=\"" << num(x) << "\" y=\"" << num(y + 4) << "\" font-weight=\"bold\">"
        << xml_escape(spec.marker_title) << "</text>\n";
    x += 8.0 * static_cast<double>(spec.marker_title.size()) + 14;
    for (std::size_t i = 0; i < spec.marker_labels.size(); ++i) {
      marker(out, static_cast<int>(i), x, y, "#555", false);
      out << "<text x=\"" << num(x + 9) << "\" y=\"" << num(y + 4) << "\">"
          << xml_escape(spec.marker_labels[i]) << "</text>\n";
      x += 18 + 7.5 * static_cast<double>(spec.marker_labels[i].size()) + 10;
    }
    x += 16;
    // A front: a short polyline through a ringed point.
    auto front_sample = [&](double at, double y0, const PlotSeries& series) {
      out << "<polyline points=\"" << num(at) << "," << num(y0 + 3) << " " << num(at + 14) << ","
          << num(y0 - 3) << " " << num(at + 28) << "," << num(y0) << "\" " << front_stroke(series) << "/>";
      ring(out, at + 14, y0 - 3, series.front_color);
    };
    if (spec.series.size() <= 1) {
      front_sample(x, y, spec.series.empty() ? PlotSeries{} : spec.series.front());
      out << "<text x=\"" << num(x + 36) << "\" y=\"" << num(y + 4) << "\">" << xml_escape(spec.front_label)
          << "</text>\n";
      x += 36 + 7.5 * static_cast<double>(spec.front_label.size()) + 16;
    }
    out << "<line x1=\"" << num(x) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x + 28) << "\" y2=\""
        << num(y) << "\" stroke=\"#888\" stroke-width=\"1.4\" stroke-dasharray=\"5,3\"/>";
    out << "<text x=\"" << num(x + 36) << "\" y=\"" << num(y + 4) << "\">" << xml_escape(spec.floor_label)
        << "</text>\n";
    x += 36 + 7.0 * static_cast<double>(spec.floor_label.size()) + 16;
    if (!spec.faded_label.empty()) {
      marker(out, 0, x, y, "#555", false, true);
      out << "<text x=\"" << num(x + 9) << "\" y=\"" << num(y + 4) << "\">" << xml_escape(spec.faded_label)
          << "</text>\n";
    }
    // Series: each one's paint and its front.
    if (spec.series.size() > 1) {
      x = kMargin;
      y += 24;
      out << "<text x=\"" << num(x) << "\" y=\"" << num(y + 4) << "\" font-weight=\"bold\">"
          << xml_escape(spec.series_title) << "</text>\n";
      x += 8.0 * static_cast<double>(spec.series_title.size()) + 14;
      for (const PlotSeries& series : spec.series) {
        marker(out, 0, x, y, "#555", series.hollow);
        front_sample(x + 14, y, series);
        const std::string text = series.label + ": " + (series.hollow ? "hollow" : "filled") + " markers, " +
                                 (series.front_dash.empty() ? "solid" : "dashed") + " " + spec.front_label;
        out << "<text x=\"" << num(x + 50) << "\" y=\"" << num(y + 4) << "\">" << xml_escape(text)
            << "</text>\n";
        x += 50 + 7.0 * static_cast<double>(text.size()) + 24;
      }
    }
    out << "</g>\n";
  }

  for (std::size_t i = 0; i < spec.panels.size(); ++i) {
    const PlotPanel& p = spec.panels[i];
    const int row = static_cast<int>(i) / columns, col = static_cast<int>(i) % columns;
    const Range yr = (spec.share_y_by_row ? row_y[static_cast<std::size_t>(row)] : all_y).decades();
    const double left = kMargin + col * kPanelWidth + kPadLeft;
    const double right = kMargin + (col + 1) * kPanelWidth - kPadRight;
    const double top = grid_top + row * kPanelHeight + kPadTop;
    const double bottom = grid_top + (row + 1) * kPanelHeight - kPadBottom;
    auto px = [&](double v) { return scale(v, xr, left, right); };
    auto py = [&](double v) { return scale(v, yr, bottom, top); };

    out << "<g>\n<text x=\"" << num(left) << "\" y=\"" << num(top - 8)
        << "\" font-size=\"13\" font-weight=\"bold\">" << xml_escape(p.title) << "</text>\n";
    out << "<rect x=\"" << num(left) << "\" y=\"" << num(top) << "\" width=\"" << num(right - left)
        << "\" height=\"" << num(bottom - top)
        << "\" fill=\"#fbfbfb\" stroke=\"#333\" stroke-width=\"1\"/>\n";
    // Grid, ticks and labels: decades labelled, 2..9 as short ticks.
    for (int d = xr.lo; d <= xr.hi; ++d) {
      const double x = px(std::pow(10.0, d));
      if (d > xr.lo && d < xr.hi)
        out << "<line x1=\"" << num(x) << "\" y1=\"" << num(top) << "\" x2=\"" << num(x) << "\" y2=\""
            << num(bottom) << "\" stroke=\"#ddd\"/>";
      out << "<line x1=\"" << num(x) << "\" y1=\"" << num(bottom) << "\" x2=\"" << num(x) << "\" y2=\""
          << num(bottom + 5) << "\" stroke=\"#333\"/>";
      out << "<text x=\"" << num(x) << "\" y=\"" << num(bottom + 17)
          << "\" font-size=\"11\" text-anchor=\"middle\">"
          << xml_escape(spec.x_tick ? spec.x_tick(d) : superscript_power(d)) << "</text>\n";
      if (d < xr.hi)
        for (int k = 2; k <= 9; ++k) {
          const double xm = px(k * std::pow(10.0, d));
          out << "<line x1=\"" << num(xm) << "\" y1=\"" << num(bottom) << "\" x2=\"" << num(xm) << "\" y2=\""
              << num(bottom + 3) << "\" stroke=\"#333\"/>";
        }
    }
    for (int d = yr.lo; d <= yr.hi; ++d) {
      const double y = py(std::pow(10.0, d));
      if (d > yr.lo && d < yr.hi)
        out << "<line x1=\"" << num(left) << "\" y1=\"" << num(y) << "\" x2=\"" << num(right) << "\" y2=\""
            << num(y) << "\" stroke=\"#ddd\"/>";
      out << "<line x1=\"" << num(left - 5) << "\" y1=\"" << num(y) << "\" x2=\"" << num(left) << "\" y2=\""
          << num(y) << "\" stroke=\"#333\"/>";
      out << "<text x=\"" << num(left - 8) << "\" y=\"" << num(y + 4)
          << "\" font-size=\"11\" text-anchor=\"end\">"
          << xml_escape(spec.y_tick ? spec.y_tick(d) : superscript_power(d)) << "</text>\n";
      if (d < yr.hi)
        for (int k = 2; k <= 9; ++k) {
          const double ym = py(k * std::pow(10.0, d));
          out << "<line x1=\"" << num(left - 3) << "\" y1=\"" << num(ym) << "\" x2=\"" << num(left)
              << "\" y2=\"" << num(ym) << "\" stroke=\"#333\"/>";
        }
    }
    if (row == rows - 1)
      out << "<text x=\"" << num(0.5 * (left + right)) << "\" y=\"" << num(bottom + 33)
          << "\" font-size=\"12\" text-anchor=\"middle\">" << xml_escape(spec.x_label) << "</text>\n";
    if (col == 0) {
      const double cx = left - 58, cy = 0.5 * (top + bottom);  // clear of the widest tick label ("0.1 mm")
      out << "<text x=\"" << num(cx) << "\" y=\"" << num(cy)
          << "\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 " << num(cx) << " " << num(cy)
          << ")\">" << xml_escape(spec.y_label) << "</text>\n";
    }
    if (p.floor) {
      const double y = py(*p.floor);
      out << "<line x1=\"" << num(left) << "\" y1=\"" << num(y) << "\" x2=\"" << num(right) << "\" y2=\""
          << num(y) << "\" stroke=\"#888\" stroke-width=\"1.4\" stroke-dasharray=\"5,3\"/>\n";
    }
    // Points, then the front over them.
    // Series by series, so that hollow markers lie on filled ones.
    const PlotSeries plain;
    auto series_of = [&](int k) -> const PlotSeries& {
      return k >= 0 && static_cast<std::size_t>(k) < spec.series.size()
                 ? spec.series[static_cast<std::size_t>(k)]
                 : plain;
    };
    for (std::size_t si = 0; si < std::max<std::size_t>(spec.series.size(), 1); ++si)
      for (const PlotPoint& q : p.points) {
        if (static_cast<std::size_t>(std::max(q.series, 0)) != si && !(si == 0 && q.series < 0)) continue;
        out << "<g>";
        if (!q.tooltip.empty()) out << "<title>" << xml_escape(q.tooltip) << "</title>";
        const std::size_t ci = static_cast<std::size_t>(std::max(q.color, 0));
        marker(out, q.marker, px(q.x), py(q.y), ci < spec.colors.size() ? spec.colors[ci] : "#000",
               series_of(q.series).hollow, q.faded);
        out << "</g>\n";
      }
    for (const PlotFront& f : p.fronts) {
      if (f.points.empty()) continue;
      const PlotSeries& series = series_of(f.series);
      out << "<polyline " << front_stroke(series) << " points=\"";
      for (const auto& [x, y] : f.points) out << num(px(x)) << "," << num(py(y)) << " ";
      out << "\"/>\n";
      for (const auto& [x, y] : f.points) ring(out, px(x), py(y), series.front_color), out << "\n";
    }
    out << "</g>\n";
  }
  out << "</svg>\n";
  std::string s = out.str();
  return s;
}

}  // namespace tirectl
