#pragma once
// The viewer's ImGui panel: a control for every setting (method, n, c, NDF, generation path,
// effects, debug view, exposure, split view), the stacked per-pass GPU timing graph over the
// last frames, the frame's stats and a legend for the debug view or split view on screen.
// Widgets only: it edits Controls' settings and returns what was clicked.

#include "samples/viewer/controls.h"
#include "samples/viewer/timing_history.h"
#include "samples/viewer/view_renderer.h"

#include <optional>

namespace agaa::viewer {

struct PanelStats {
    uint32_t width = 0, height = 0;             // the window (swapchain)
    uint32_t renderWidth = 0, renderHeight = 0; // rendered (smaller with pixel size above 1)
    double fps = 0.0;
    const ViewFrame* frame = nullptr;     // the last presented frame
    std::optional<double> eventsPerPixel; // last measured
    std::string error;                    // the last refused setting, shown in red
};

struct PanelActions {
    bool reset = false;
    bool screenshot = false;
};

// The settings panel (left, full height) and the timing window (bottom right), in pixels: the
// scripted screenshot check looks at the scene outside both.
inline constexpr float kPanelWidth = 250.0f;
inline constexpr float kTimingWidth = 390.0f, kTimingHeight = 190.0f;

PanelActions drawPanel(Controls& controls, const TimingHistory& timings, const PanelStats& stats);

} // namespace agaa::viewer
