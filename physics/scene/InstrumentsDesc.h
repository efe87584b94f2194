#pragma once
// What a lesson measures with (CONTRACT §7 `instruments`, format version 2): saved with the
// scene so that it opens ready to measure. Plain data; the app's instruments fill it at save
// and are set from it at load, the command line adds its probes to `run`'s output, and
// checkInstruments() (InstrumentValidation.h) checks its probes and ends against the world.
//
// An end (of a ruler, a protractor, a probe's argument) is an object id or a fixed point
// "X:Y" in metres, as the probes' arguments are.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox {

// A graph of probe y against time (x empty) or against probe x.
struct GraphDesc {
    std::string y;
    std::string x;
};

struct RulerDesc {
    std::array<std::string, 2> ends;
};

// ∠ABC: the vertex is the middle end, as in the probe angle(A,B,C).
struct ProtractorDesc {
    std::array<std::string, 3> ends;
};

// The canvas's view: the world point at its centre and the width it shows, in metres.
struct ViewDesc {
    std::array<double, 2> center{0.0, 0.0};
    double width = 10.0;
};

struct InstrumentsDesc {
    std::vector<std::string> probes;  // the data table's columns
    std::vector<GraphDesc> graphs;
    std::vector<std::string> timers;  // period timers, by probe
    bool stopwatch = false;           // the lesson times by hand: the dock opens on it
    std::vector<RulerDesc> rulers;
    std::vector<ProtractorDesc> protractors;
    std::string freeBody;  // the body the free-body view shows; "" = the view is off
    std::optional<ViewDesc> view;
    std::vector<std::string> plots;  // the plots shown (kPlotNames); empty: energy and phase

    bool empty() const {
        return probes.empty() && graphs.empty() && timers.empty() && !stopwatch && rulers.empty() &&
               protractors.empty() && freeBody.empty() && !view && plots.empty();
    }
    // Every probe the instruments read, once each, in the order: table, graphs (y, then x),
    // timers. The command line adds these to `run`'s output.
    std::vector<std::string> readProbes() const {
        std::vector<std::string> out;
        auto add = [&](const std::string& p) {
            if (p.empty()) return;
            for (const std::string& q : out)
                if (q == p) return;
            out.push_back(p);
        };
        for (const std::string& p : probes) add(p);
        for (const GraphDesc& g : graphs) {
            add(g.y);
            add(g.x);
        }
        for (const std::string& p : timers) add(p);
        return out;
    }
};

// The names of the plots `plots` may list.
inline constexpr std::string_view kPlotNames[] = {"energy", "phase", "error"};

}  // namespace phasebox
