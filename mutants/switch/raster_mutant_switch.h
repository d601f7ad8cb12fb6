// The runtime switch of the schemata build: which catalogue entry is on (RASTER_MUTANT=name) and which sites ran.
#pragma once

#include <atomic>

namespace raster_mutant {

struct State {
    int active = -1;                          // the site switched on, -1 for none (the correct build)
    std::atomic<unsigned char>* reached;      // one flag per site: its code ran in this process
};

// Reads RASTER_MUTANT once; an unknown name stops the process (exit 2) rather than run the correct code silently.
// With RASTER_MUTANT_TRACE=DIR, the process writes DIR/PID.trace at exit: its command line and its ancestors', and
// the sites it reached.
State load_state();

inline const State& state() {
    static const State loaded = load_state();
    return loaded;
}

inline bool on(int site) {
    const State& s = state();
    s.reached[site].store(1, std::memory_order_relaxed);
    return s.active == site;
}

}  // namespace raster_mutant
