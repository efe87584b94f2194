#pragma once
// What the benchmark programs share: the command line (--steps, --repeat, --json), medians,
// a compiler barrier, and a small JSON writer. Header-only because each bench_*.cpp is its
// own executable (tests/bench/CMakeLists.txt globs them) and there is no bench library.

#include "physics/scene/SceneDesc.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox::bench {

using Clock = std::chrono::steady_clock;

inline double secondsBetween(Clock::time_point start, Clock::time_point end) {
    return std::chrono::duration<double>(end - start).count();
}

// The median, not the mean: one repeat disturbed by another process (others build on the
// same two cores) must not move the figure.
inline double median(std::vector<double> values) {
    if (values.empty()) return std::nan("");
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

// Tells the compiler that the memory behind p is read and written here, so stores into it
// cannot be dropped and loops over it cannot be merged across calls.
inline void clobber(const void* p) {
    __asm__ __volatile__("" : : "r"(p) : "memory");
}

struct Options {
    int steps = 0;   // 0 = the program's default
    int repeat = 0;  // 0 = the program's default
    bool json = false;
    bool breakdown = false;
    bool quick = false;
    std::vector<std::string_view> flags;  // the other extra flags given
    bool has(std::string_view flag) const {
        return std::find(flags.begin(), flags.end(), flag) != flags.end();
    }
};

// Accepts --steps N, --repeat N, --json and the flags the caller lists in extraFlags
// ("--breakdown" and "--quick" set their fields, the others are kept in flags). Exits with a usage
// message on anything else.
inline Options parseOptions(int argc, char** argv, std::string_view usage,
                            std::vector<std::string_view> extraFlags = {}) {
    Options options;
    const auto fail = [&](const std::string& message) {
        if (!message.empty()) std::fprintf(stderr, "%s\n", message.c_str());
        std::fprintf(message.empty() ? stdout : stderr, "usage: %s %.*s\n", argv[0],
                     static_cast<int>(usage.size()), usage.data());
        std::exit(message.empty() ? 0 : 2);
    };
    const auto positive = [&](int& i) {
        if (i + 1 >= argc) fail(std::string(argv[i]) + " needs a number");
        char* end = nullptr;
        const long value = std::strtol(argv[++i], &end, 10);
        if (*end != '\0' || value < 1 || value > 100000000)
            fail(std::string(argv[i - 1]) + " needs a positive integer");
        return static_cast<int>(value);
    };
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        const bool extra = std::find(extraFlags.begin(), extraFlags.end(), arg) != extraFlags.end();
        if (arg == "--steps")
            options.steps = positive(i);
        else if (arg == "--repeat")
            options.repeat = positive(i);
        else if (arg == "--json")
            options.json = true;
        else if (extra && arg == "--breakdown")
            options.breakdown = true;
        else if (extra && arg == "--quick")
            options.quick = true;
        else if (extra)
            options.flags.push_back(arg);
        else if (arg == "--help" || arg == "-h")
            fail("");
        else
            fail("unknown option " + std::string(arg));
    }
    return options;
}

// A minimal JSON writer: enough for flat objects and arrays of them, with keys in the order
// written (scripts read the keys, people read the order).
class Json {
public:
    void beginObject(std::string_view key = {}) { open(key, '{'); }
    void endObject() { close('}'); }
    void beginArray(std::string_view key = {}) { open(key, '['); }
    void endArray() { close(']'); }

    void value(std::string_view key, double v) {
        char buf[64];
        // JSON has no NaN or infinity: a figure that does not exist is null.
        if (std::isfinite(v))
            std::snprintf(buf, sizeof buf, "%.6g", v);
        else
            std::snprintf(buf, sizeof buf, "null");
        raw(key, buf);
    }
    void value(std::string_view key, long long v) { raw(key, std::to_string(v)); }
    void value(std::string_view key, int v) { raw(key, std::to_string(v)); }
    void value(std::string_view key, bool v) { raw(key, v ? "true" : "false"); }
    void value(std::string_view key, std::string_view v) { raw(key, quote(v)); }
    void value(std::string_view key, const char* v) { value(key, std::string_view(v)); }

    const std::string& str() const { return out_; }

private:
    static std::string quote(std::string_view s) {
        std::string out = "\"";
        for (const char c : s) {
            if (c == '"' || c == '\\') {
                out += '\\';
                out += c;
            } else if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += c;
            }
        }
        return out + "\"";
    }
    void separator(std::string_view key) {
        if (needComma_) out_ += ',';
        if (!key.empty()) out_ += quote(key) + ':';
    }
    void open(std::string_view key, char bracket) {
        separator(key);
        out_ += bracket;
        needComma_ = false;
    }
    void close(char bracket) {
        out_ += bracket;
        needComma_ = true;
    }
    void raw(std::string_view key, const std::string& text) {
        separator(key);
        out_ += text;
        needComma_ = true;
    }

    std::string out_;
    bool needComma_ = false;
};

// count particles started at one point, with particle collisions on and nothing else (no
// gravity): the worst start a pile can have (bench_piles, bench_threads).
inline SceneDesc pileAtPoint(int count) {
    SceneDesc s;
    s.name = "Pile at a point";
    s.effects.particleCollisions = ParticleCollisionsDesc{};
    for (int i = 0; i < count; ++i) s.particles.push_back(ParticleDesc{});
    return s;
}

}  // namespace phasebox::bench
