// Every property of the suite, written once where its check is defined (RASTER_PROPERTY) and registered at static
// initialisation, so the property gtests and the mutants run both take the list from here.
#pragma once

#include <string>
#include <vector>

#include "properties/implementation.h"

namespace raster::properties {

struct Property {
    std::string suite;                     // the gtest suite, e.g. "Coverage"
    std::string name;                      // the gtest name, e.g. "sharedEdgeSamplesCoveredExactlyOnce"
    void (*check)(const Implementation&);  // draws its own cases with RapidCheck; fails through RC_ASSERT/fail_case
    bool draws = false;                    // rasterizes (stage_driver.h), so it runs on every drawing backend
    bool any_renderer = false;             // draws only whole frames (draw, coverage_counts, render_with), so it
                                           // also runs on a plugin (implementation.h)
    std::string file;                      // where the property is written, for gtest's failure locations
    int line = 0;
};

// Adds a property to the registry; RASTER_PROPERTY calls it during static initialisation. Returns true so that
// the call can initialise a namespace-scope constant.
bool register_property(const char* suite, const char* name, void (*check)(const Implementation&), bool draws,
                       bool any_renderer, const char* file, int line);

// The registered properties in the order of docs/properties.md: by suite, in the order property_registry.cpp declares the
// suites, then in the order they are written. Throws std::logic_error naming a suite that order does not list.
const std::vector<Property>& all_properties();

}  // namespace raster::properties

// Defines the property Suite.Name and registers it: the braces that follow are its check, run against `impl`.
// Write it in namespace raster::properties, in a source of the raster_property_checks object library (an object
// library, so that the linker keeps every registration; properties/CMakeLists.txt). RASTER_PROPERTY is for a check
// that never rasterizes; RASTER_DRAWING_PROPERTY for one that does (through stage_driver.h), which then runs once
// per drawing backend (implementation.h), as the gtest Suite.Name/backend; RASTER_RENDERER_PROPERTY for a drawing
// one whose every draw is a whole frame through draw, coverage_counts or render_with (triangles in, samples out, no
// stage of raster's called for what it checks), which then also runs on the plugin backends. The registry's test
// checks the choice, and a renderer property that reaches raster's stages fails on a plugin, saying so.
#define RASTER_PROPERTY_WITH(Suite, Name, Draws, AnyRenderer)                                                \
    static void raster_property_##Suite##_##Name(const ::raster::properties::Implementation& impl);          \
    [[maybe_unused]] static const bool raster_property_registered_##Suite##_##Name =                         \
        ::raster::properties::register_property(#Suite, #Name, raster_property_##Suite##_##Name, Draws,      \
                                                AnyRenderer, __FILE__, __LINE__);                            \
    static void raster_property_##Suite##_##Name(const ::raster::properties::Implementation& impl)
#define RASTER_PROPERTY(Suite, Name) RASTER_PROPERTY_WITH(Suite, Name, false, false)
#define RASTER_DRAWING_PROPERTY(Suite, Name) RASTER_PROPERTY_WITH(Suite, Name, true, false)
#define RASTER_RENDERER_PROPERTY(Suite, Name) RASTER_PROPERTY_WITH(Suite, Name, true, true)
