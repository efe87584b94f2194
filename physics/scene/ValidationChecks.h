#pragma once
// What the scene's checks share (SceneValidation.cpp, JointValidation.cpp): the Checker that
// collects issues with their JSON-style paths, the helpers that spell paths, names and numbers
// in its messages, checkFields(), which checks a kind's fields against its table, and
// checkJoints(), which validateScene() calls for the joints. Private to physics/scene.

#include "physics/scene/SceneDesc.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace phasebox::validation {

// For the messages (SceneValidation.cpp): a name from the file in quotes, cut when long; the
// shortest text that reads back as v; the paths array[i] and path.key.
std::string quoted(const std::string& text);
std::string fmt(double v);
std::string at(std::string_view array, std::size_t i);
std::string join(const std::string& path, std::string_view key);

// Collects issues with JSON-style paths: check(path, condition, message).
class Checker {
public:
    explicit Checker(std::vector<SceneIssue>& out) : out_(out) {}

    void fail(const std::string& path, const std::string& message) {
        out_.push_back({path, message});
    }
    // Each numeric check first requires a finite number; each returns whether v passed, so
    // that checks chain (positive, then at most the limit) and report one problem per value.
    bool finite(const std::string& path, double v) {
        if (std::isfinite(v)) return true;
        fail(path, "must be a finite number");
        return false;
    }
    bool positive(const std::string& path, double v, double max = kNoLimit) {
        if (!finite(path, v)) return false;
        if (!(v > 0.0)) return fails(path, "must be > 0 (got " + fmt(v) + ")");
        return atMost(path, v, max);
    }
    bool nonNegative(const std::string& path, double v, double max = kNoLimit) {
        if (!finite(path, v)) return false;
        if (v < 0.0) return fails(path, "must be >= 0 (got " + fmt(v) + ")");
        return atMost(path, v, max);
    }
    bool unitInterval(const std::string& path, double v) {
        if (finite(path, v) && (v < 0.0 || v > 1.0))
            return fails(path, "must be between 0 and 1 (got " + fmt(v) + ")");
        return std::isfinite(v);
    }
    // A signed value: finite and |v| <= limit.
    bool magnitude(const std::string& path, double v, double limit) {
        if (!finite(path, v)) return false;
        if (std::abs(v) > limit)
            return fails(path, "must be between -" + fmt(limit) + " and " + fmt(limit) + " (got " +
                                   fmt(v) + ")");
        return true;
    }
    bool atMost(const std::string& path, double v, double max) {
        if (v > max) return fails(path, "must be <= " + fmt(max) + " (got " + fmt(v) + ")");
        return true;
    }
    bool atLeast(const std::string& path, double v, double min) {
        if (v < min) return fails(path, "must be >= " + fmt(min) + " (got " + fmt(v) + ")");
        return true;
    }
    static constexpr double kNoLimit = std::numeric_limits<double>::infinity();

private:
    bool fails(const std::string& path, const std::string& message) {
        fail(path, message);
        return false;
    }

    std::vector<SceneIssue>& out_;
};

// Every field of d whose table gives a range or rule. Defined in SceneValidation.cpp, which
// instantiates it for what it checks and for JointDesc.
template <typename D>
void checkFields(Checker& check, const std::string& path, const D& d);

// validateScene()'s bookkeeping of ids, for the joints: claim(path, id, body, isDefault) takes
// an id for its holder at path; reference(where, id, what) says whether id names a body, and if
// not says so at where.
using ClaimId =
    std::function<void(const std::string& path, const std::string& id, bool body, bool isDefault)>;
using ReferenceId =
    std::function<bool(const std::string& where, const std::string& id, std::string_view what)>;

// The joints (JointValidation.cpp).
void checkJoints(Checker& check, const SceneDesc& scene, const ClaimId& claim,
                 const ReferenceId& reference);

}  // namespace phasebox::validation
