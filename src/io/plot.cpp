#include "io/plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "image/image_library.h"
#include "io/image_output.h"
#include "image/image.h"

namespace glint::io {
namespace {

constexpr int kFontSize = 13;

std::string find_font() {
    for (const char* p : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                          "/usr/share/fonts/dejavu/DejaVuSans.ttf",
                          "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf"}) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(p, ec)) return p;
    }
    return "";  // OpenImageIO's own search
}

// Decades [lo, hi] (exponents) covering the positive values, at least one decade wide.
void decade_range(const std::vector<const std::vector<double>*>& values, int* lo, int* hi) {
    double mn = std::numeric_limits<double>::infinity(), mx = 0;
    for (const std::vector<double>* v : values)
        for (double x : *v)
            if (x > 0 && std::isfinite(x)) {
                mn = std::min(mn, x);
                mx = std::max(mx, x);
            }
    if (!(mx > 0)) {
        *lo = 0;
        *hi = 1;
        return;
    }
    // A little slack so points on a decade do not sit on the frame.
    *lo = static_cast<int>(std::floor(std::log10(mn) - 1e-9));
    *hi = static_cast<int>(std::ceil(std::log10(mx) + 1e-9));
    if (*hi <= *lo) *hi = *lo + 1;
}

// Text alignment, as image/image_library.h's DrawOp takes it.
enum class AX { Left = -1, Center = 0, Right = 1 };
enum class AY { Top = -1, Center = 0, Bottom = 1 };

// Collects the drawing, which OpenImageIO (the image module) renders when it is written.
class Canvas {
public:
    Canvas(int w, int h) : w_(w), h_(h) {}
    void line(int x0, int y0, int x1, int y1, const std::array<float, 3>& c) {
        add(DrawOp::Kind::Line, x0, y0, x1, y1, c);
    }
    void box(int x0, int y0, int x1, int y1, const std::array<float, 3>& c, bool fill) {
        add(fill ? DrawOp::Kind::FilledBox : DrawOp::Kind::Box, x0, y0, x1, y1, c);
    }
    void text(int x, int y, const std::string& s, AX ax, AY ay) {
        DrawOp& op = add(DrawOp::Kind::Text, x, y, x, y, {0, 0, 0});
        op.text = s;
        op.font = font_;
        op.font_size = kFontSize;
        op.align_x = static_cast<int>(ax);
        op.align_y = static_cast<int>(ay);
    }
    // Writes the image; returns why text could not be drawn (no font), empty otherwise.
    std::string write(const std::string& path) const {
        std::vector<float> rgb;
        const std::string text_error = image_library().draw(w_, h_, ops_, &rgb);
        Image image;
        image.width = w_;
        image.height = h_;
        image.rgba.assign(static_cast<size_t>(w_) * h_ * 4, 1.0f);
        for (size_t i = 0; i < rgb.size() / 3; ++i)
            for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = rgb[i * 3 + c];
        OutputEncoding identity;  // the drawn values are the code values
        identity.transfer = OutputEncoding::Transfer::Linear;
        write_image(image, path, identity);
        return text_error;
    }

private:
    DrawOp& add(DrawOp::Kind kind, int x0, int y0, int x1, int y1,
                const std::array<float, 3>& c) {
        DrawOp& op = ops_.emplace_back();
        op.kind = kind;
        op.x0 = x0;
        op.y0 = y0;
        op.x1 = x1;
        op.y1 = y1;
        for (int k = 0; k < 3; ++k) op.color[k] = c[k];
        return op;
    }

    int w_, h_;
    std::vector<DrawOp> ops_;
    std::string font_ = find_font();
};

}  // namespace

namespace {

double safe_log(double v) { return std::log10(std::max(v, 1e-30)); }

// Along the line through (a0, b0) and (a1, b1) in log-log space: b at a.
double along(double a0, double b0, double a1, double b1, double a) {
    const double la0 = safe_log(a0), la1 = safe_log(a1);
    if (la1 == la0) return b0;
    const double t = (safe_log(a) - la0) / (la1 - la0);
    return std::pow(10.0, safe_log(b0) + t * (safe_log(b1) - safe_log(b0)));
}

}  // namespace

CurveReading curve_y_at_x(const std::vector<double>& x, const std::vector<double>& y, double at) {
    CurveReading r;
    const size_t n = std::min(x.size(), y.size());
    if (n == 1 && x[0] == at) return {CurveReading::Where::Interpolated, y[0]};
    if (n < 2) return r;
    for (size_t i = 0; i + 1 < n; ++i) {
        const double lo = std::min(x[i], x[i + 1]), hi = std::max(x[i], x[i + 1]);
        if (at >= lo && at <= hi)
            return {CurveReading::Where::Interpolated, along(x[i], y[i], x[i + 1], y[i + 1], at)};
    }
    if (at < x[0]) return {CurveReading::Where::Before, y[0]};
    return {CurveReading::Where::Extrapolated, along(x[n - 2], y[n - 2], x[n - 1], y[n - 1], at)};
}

CurveReading curve_x_at_y(const std::vector<double>& x, const std::vector<double>& y,
                          double level) {
    CurveReading r;
    const size_t n = std::min(x.size(), y.size());
    if (n == 0) return r;
    if (y[0] <= level) return {CurveReading::Where::AtMost, x[0]};
    for (size_t i = 0; i + 1 < n; ++i)
        if (y[i] > level && y[i + 1] <= level)
            return {CurveReading::Where::Interpolated, along(y[i], x[i], y[i + 1], x[i + 1], level)};
    if (n >= 2 && y[n - 1] < y[n - 2])
        return {CurveReading::Where::Extrapolated,
                along(y[n - 2], x[n - 2], y[n - 1], x[n - 1], level)};
    return r;
}

std::string decade_label(int e) {
    if (e >= 0 && e <= 3) {
        std::string s = "1";
        s.append(static_cast<size_t>(e), '0');
        return s;
    }
    if (e < 0 && e >= -3) return "0." + std::string(static_cast<size_t>(-e - 1), '0') + "1";
    return "1e" + std::to_string(e);
}

std::string write_loglog_plot(const std::vector<PlotSeries>& series, const PlotOptions& options,
                              const std::string& path) {
    const int w = std::max(200, options.width), h = std::max(150, options.height);
    Canvas canvas(w, h);
    // Plot area: room for tick labels left and below, the title above.
    const int left = 70, right = w - 20, top = 34, bottom = h - 46;
    std::vector<const std::vector<double>*> xs, ys;
    for (const PlotSeries& s : series) {
        xs.push_back(&s.x);
        ys.push_back(&s.y);
    }
    int x_lo, x_hi, y_lo, y_hi;
    decade_range(xs, &x_lo, &x_hi);
    decade_range(ys, &y_lo, &y_hi);
    auto px = [&](double x) {
        const double t = x > 0 ? (std::log10(x) - x_lo) / (x_hi - x_lo) : 0.0;
        return left + static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * (right - left)));
    };
    auto py = [&](double y) {
        const double t = y > 0 ? (std::log10(y) - y_lo) / (y_hi - y_lo) : 0.0;
        return bottom - static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * (bottom - top)));
    };
    const std::array<float, 3> black{0, 0, 0}, grid{0.85f, 0.85f, 0.85f};
    // Decade grid, ticks (minor at 2..9) and labels; every other label past 8 decades.
    const int x_step = (x_hi - x_lo) > 8 ? 2 : 1, y_step = (y_hi - y_lo) > 8 ? 2 : 1;
    for (int e = x_lo; e <= x_hi; ++e) {
        const int x = px(std::pow(10.0, e));
        canvas.line(x, top, x, bottom, grid);
        canvas.line(x, bottom, x, bottom + 6, black);
        if ((e - x_lo) % x_step == 0) canvas.text(x, bottom + 9, decade_label(e), AX::Center, AY::Top);
        if (e < x_hi)
            for (int m = 2; m <= 9; ++m) {
                const int xm = px(m * std::pow(10.0, e));
                canvas.line(xm, bottom, xm, bottom + 3, black);
            }
    }
    for (int e = y_lo; e <= y_hi; ++e) {
        const int y = py(std::pow(10.0, e));
        canvas.line(left, y, right, y, grid);
        canvas.line(left - 6, y, left, y, black);
        if ((e - y_lo) % y_step == 0) canvas.text(left - 9, y, decade_label(e), AX::Right, AY::Center);
        if (e < y_hi)
            for (int m = 2; m <= 9; ++m) {
                const int ym = py(m * std::pow(10.0, e));
                canvas.line(left - 3, ym, left, ym, black);
            }
    }
    canvas.box(left, top, right, bottom, black, false);
    if (!options.title.empty()) canvas.text(w / 2, 8, options.title, AX::Center, AY::Top);
    if (!options.x_label.empty())
        canvas.text((left + right) / 2, h - 6, options.x_label, AX::Center, AY::Bottom);
    if (!options.y_label.empty()) canvas.text(8, 8, options.y_label, AX::Left, AY::Top);

    // Curves: two-pixel lines, a 5x5 marker on each point.
    for (const PlotSeries& s : series) {
        const size_t n = std::min(s.x.size(), s.y.size());
        for (size_t i = 0; i < n; ++i) {
            const int x = px(s.x[i]), y = py(s.y[i]);
            canvas.box(x - 2, y - 2, x + 2, y + 2, s.color, true);
            if (i > 0) {
                const int x0 = px(s.x[i - 1]), y0 = py(s.y[i - 1]);
                canvas.line(x0, y0, x, y, s.color);
                canvas.line(x0, y0 + 1, x, y + 1, s.color);
            }
        }
    }
    // Legend in the top-right corner of the plot area.
    if (!series.empty()) {
        size_t longest = 0;
        for (const PlotSeries& s : series) longest = std::max(longest, s.name.size());
        const int lw = 40 + static_cast<int>(longest) * 8, lh = 8 + 18 * int(series.size());
        const int lx = right - lw - 8, ly = top + 8;
        canvas.box(lx, ly, lx + lw, ly + lh, {1, 1, 1}, true);
        canvas.box(lx, ly, lx + lw, ly + lh, black, false);
        for (size_t i = 0; i < series.size(); ++i) {
            const int y = ly + 13 + 18 * static_cast<int>(i);
            canvas.line(lx + 6, y, lx + 28, y, series[i].color);
            canvas.line(lx + 6, y + 1, lx + 28, y + 1, series[i].color);
            canvas.box(lx + 15, y - 2, lx + 19, y + 2, series[i].color, true);
            canvas.text(lx + 34, y, series[i].name, AX::Left, AY::Center);
        }
    }
    return canvas.write(path);
}

}  // namespace glint::io
