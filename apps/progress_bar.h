// A one-line progress bar on stderr for the long-running subcommands (report, tradeoff), drawn only on a terminal.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <ostream>
#include <string>

namespace raster::cli {

// Redraws "[####------] done/total label" in place on `err` when stderr is a terminal, and does nothing otherwise
// (so logs and tests never see it). finish() erases the line, so ordinary output can follow.
class ProgressBar {
public:
    ProgressBar(std::ostream& err, size_t total) : err_(err), total_(total), enabled_(::isatty(STDERR_FILENO) == 1) {}
    void show(size_t done, const std::string& label) {
        if (!enabled_) return;
        constexpr int kWidth = 30;
        const int filled = total_ ? static_cast<int>(kWidth * done / total_) : kWidth;
        err_ << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, '-') << "] " << done << "/" << total_
             << " " << label << "\x1b[K" << std::flush;
    }
    void finish() {
        if (enabled_) err_ << "\r\x1b[K" << std::flush;
    }

private:
    std::ostream& err_;
    size_t total_;
    bool enabled_;
};

}  // namespace raster::cli
