#include "app/progress.h"

#include <algorithm>
#include <cmath>

namespace glint::app {

void ProgressReporter::update(double fraction) {
    if (style_ == ProgressStyle::None) return;
    if (!(fraction >= 0)) fraction = 0;  // NaN too
    fraction = std::min(fraction, 1.0);
    // Hundredths: the lines contract has two decimals and the bar shows whole percent.
    int step = static_cast<int>(std::floor(fraction * 100.0 + 1e-9));
    std::lock_guard<std::mutex> lock(mutex_);
    if (done_ || step <= shown_) return;
    shown_ = step;
    if (style_ == ProgressStyle::Lines) {
        std::fprintf(out_, "progress %.2f\n", step / 100.0);
    } else {
        draw_bar(step);
    }
    std::fflush(out_);
}

void ProgressReporter::draw_bar(int percent) {
    constexpr int kWidth = 40;
    int filled = percent * kWidth / 100;
    std::fputc('\r', out_);
    std::fputc('[', out_);
    for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : '.', out_);
    std::fprintf(out_, "] %3d%%", percent);
}

void ProgressReporter::finish() {
    if (style_ == ProgressStyle::None) return;
    update(1.0);
    std::lock_guard<std::mutex> lock(mutex_);
    if (done_) return;
    done_ = true;
    if (style_ == ProgressStyle::Bar) std::fputc('\n', out_);
    std::fflush(out_);
}

void ProgressReporter::abandon() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (done_) return;
    done_ = true;
    if (style_ == ProgressStyle::Bar && shown_ >= 0) std::fputc('\n', out_);
    std::fflush(out_);
}

}  // namespace glint::app
