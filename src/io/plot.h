// A small log-log line plot written as PNG with OpenImageIO's drawing calls: what
// `glint report` draws of error against time, one curve per renderer, with decade ticks and a
// legend. No plotting library: Debian's OpenImageIO draws lines, boxes and (with a font) text.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace glint::io {

struct PlotSeries {
    std::string name;
    std::vector<double> x, y;            // points in drawing order; values <= 0 sit on the axis
    std::array<float, 3> color{0, 0, 0};  // linear 0..1, written as 8-bit code values
};

struct PlotOptions {
    int width = 640;
    int height = 400;
    std::string title;
    std::string x_label;
    std::string y_label;
};

// Draws the series on log-log axes spanning whole decades around every positive value and
// writes the picture (atomically, format from the extension). Text needs a TrueType font
// (DejaVu Sans where Debian's fonts-dejavu-core puts it, else OpenImageIO's own search); when
// none can be drawn the plot has no labels and the return value says why (empty when all text
// was drawn). Throws Error(Output) when the file cannot be written.
std::string write_loglog_plot(const std::vector<PlotSeries>& series, const PlotOptions& options,
                              const std::string& path);

// Reading a value off a curve of points (x_i, y_i) in the order given, interpolating linearly
// between log10 x and log10 y (a power law between neighbouring points). Values <= 0 count as
// 1e-30. `where` tells how the value was found.
struct CurveReading {
    enum class Where { Interpolated, Extrapolated, AtMost, Before, None } where = Where::None;
    double value = 0;
};
// y at x: the segment whose x range holds x; past the last point the last segment extended
// (Extrapolated); before the first point Before with the first y (a curve of times has no value
// before its first step). None with fewer than 2 points (or 1 point not at x).
CurveReading curve_y_at_x(const std::vector<double>& x, const std::vector<double>& y, double at);
// The smallest x at which a falling y reaches `level`: the first segment where y crosses it,
// interpolated; AtMost x_0 when the first point is already at or below the level; past the last
// point, the last segment extended (Extrapolated) when it falls, else None.
CurveReading curve_x_at_y(const std::vector<double>& x, const std::vector<double>& y,
                          double level);

// The decade tick label for 10^e: "1", "10", "0.01" for |e| <= 3, "1e-5" style beyond.
std::string decade_label(int exponent);

}  // namespace glint::io
