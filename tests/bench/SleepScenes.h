#pragma once
// The sleeping scenes that tst_sleeping checks and bench_sleeping times: the 20-row pyramid
// with simulation.sleep on or off, and the same pyramid with a 1 m box on a frictionless static
// ledge at the apex's base, sliding left at 2 m/s so that it reaches the apex's side at about
// t = 8 s, after the pyramid fell asleep.

#include "physics/scene/SceneLibrary.h"

namespace phasebox::sleep_scenes {

inline constexpr int kRows = 20;

inline SceneDesc pyramid(bool sleep) {
    SceneDesc s = scenes::pyramid(kRows);
    s.simulation.sleep = sleep;
    return s;
}

inline SceneDesc pyramidAndSlider(bool sleep) {
    SceneDesc s = pyramid(sleep);
    BoxDesc ledge;
    ledge.id = "ledge";
    ledge.isStatic = true;
    ledge.position = {9.55, 18.8};
    ledge.size = {17.0, 0.4};
    ledge.friction = 0.0;
    s.boxes.push_back(ledge);
    BoxDesc slider;
    slider.id = "slider";
    slider.position = {17.0, 19.5};
    slider.size = {1.0, 1.0};
    slider.velocity = {-2.0, 0.0};
    s.boxes.push_back(slider);
    return s;
}

}  // namespace phasebox::sleep_scenes
