#pragma once
// One input of the scene-loader fuzzer, checked end to end: parse → (validate → build → a few
// steps). Shared by the libFuzzer target (fuzz_scene_loader.cpp) and the corpus replay that
// runs in every CI build without libFuzzer (tests/app/tst_fuzz_corpus.cpp), so a reproducer
// saved in tests/fuzz/regressions/ keeps being checked by the same code that found it.
//
// Crashes, hangs, sanitizer reports and uncaught exceptions are what the fuzzer itself
// catches; the function adds the contract's promises, returned as a description of the first
// one broken (empty = all kept):
//   - a refused input gives at least one message, each naming the file;
//   - an accepted scene validates, builds without throwing, and serializes to a text that
//     loads back to the same text (no value is lost on a save);
//   - stepping never leaves a non-finite value in the world: a divergence restores the last
//     good state.

#include "app/io/SceneIO.h"
#include "physics/scene/BuildWorld.h"
#include "physics/world/World.h"

#include <QByteArray>
#include <QString>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>

namespace phasebox::fuzz {

// Beyond these sizes the input is only parsed and validated: building and stepping a scene of
// a million particles is legitimate but would cut the fuzzer to a few runs per second, and the
// code it reaches is the same as for a small one.
inline constexpr long long kMaxObjectsToBuild = 20'000;
inline constexpr long long kMaxObjectsToStep = 2'000;
inline constexpr int kSteps = 4;
inline constexpr auto kStepBudget = std::chrono::milliseconds(200);

inline long long objectCount(const SceneDesc& scene) {
    long long count = static_cast<long long>(scene.particles.size() + scene.boxes.size() +
                                             scene.planes.size() + scene.springs.size());
    for (const ClothDesc& cloth : scene.cloths)
        count += static_cast<long long>(std::max(0, cloth.resolution[0])) *
                 std::max(0, cloth.resolution[1]) * 5;  // nodes and their ~4 springs each
    return count;
}

inline QString checkSceneLoaderInput(const std::uint8_t* data, std::size_t size) {
    const QString source = QStringLiteral("fuzz.json");
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const SceneLoadResult loaded = SceneIO::parse(bytes, source);
    if (!loaded.ok()) {
        if (loaded.errors.isEmpty()) return QStringLiteral("refused without a message");
        for (const QString& error : loaded.errors)
            if (!error.startsWith(source + QLatin1Char(':')))
                return QStringLiteral("a message does not name the file: ") + error;
        return {};
    }
    const SceneDesc& scene = *loaded.scene;
    if (const auto issues = validateScene(scene); !issues.empty())
        return QStringLiteral("accepted, but validateScene() refuses it: ") +
               QString::fromStdString(issues.front().path + ": " + issues.front().message);

    // Save → load → save gives the same bytes.
    const QByteArray saved = SceneIO::serialize(scene);
    const SceneLoadResult reloaded = SceneIO::parse(saved, QStringLiteral("saved.json"));
    if (!reloaded.ok())
        return QStringLiteral("the saved scene does not load: ") + reloaded.errorText();
    if (SceneIO::serialize(*reloaded.scene) != saved)
        return QStringLiteral("the saved scene changes when loaded and saved again");

    const long long objects = objectCount(scene);
    if (objects > kMaxObjectsToBuild) return {};
    // Keep every step short: the fuzzer looks for crashes, not for slow but bounded work
    // (10,000 sub-steps or 100 Newton iterations are allowed, and take their time).
    SceneDesc fast = scene;
    fast.simulation.substeps = std::min(fast.simulation.substeps, 8);
    fast.simulation.newtonIterations = std::min(fast.simulation.newtonIterations, 4);
    fast.simulation.tolerance = std::max(fast.simulation.tolerance, 1e-6);
    try {
        BuildResult built = buildWorld(fast);
        World& world = *built.world;
        if (objects > kMaxObjectsToStep) return {};
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < kSteps && std::chrono::steady_clock::now() - start < kStepBudget; ++k) {
            const bool ok = world.step();
            if (!world.positions().allFinite() || !world.velocities().allFinite())
                return QStringLiteral("a non-finite value is left in the world after step %1 (%2)")
                    .arg(k + 1)
                    .arg(ok ? QStringLiteral("reported as good")
                            : QString::fromStdString(world.divergence()->message()));
            if (!ok && !world.divergence())
                return QStringLiteral("a failed step without a divergence report");
        }
    } catch (const std::exception& e) {
        return QStringLiteral("building or stepping a valid scene threw: ") +
               QString::fromLocal8Bit(e.what());
    }
    return {};
}

}  // namespace phasebox::fuzz
