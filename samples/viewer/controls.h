#pragma once
// What the viewer's input does: an orbit camera about the scene's bounds centre (drag to orbit,
// scroll to dolly) and the method/setting keys (1..9 method, S samples, A aggregates, D debug
// view, X compare with the reference, R reset, P screenshot). Pure logic over InputEvents: no window, no
// device.

#include "agaa/method_settings.h"
#include "engine/scene/scene.h"
#include "samples/viewer/window.h"
#include "tools/harness/frame_renderer.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <utility>

namespace agaa::viewer {

// The rates S and A cycle through: n emulated above 4 (DESIGN.md section 3), c = 1..4.
inline constexpr uint32_t kSampleCycle[] = {4, 8, 16, 32};
inline constexpr uint32_t kMaxAggregates = 4;

// Orbits the scene camera's view about a pivot: yaw about world +Y (eng::frame::orbitView),
// pitch about the camera's own horizontal axis, dolly along the line to the pivot.
class OrbitCamera {
  public:
    OrbitCamera(const glm::mat4& baseView, const glm::vec3& pivot) : m_baseView(baseView), m_pivot(pivot) {}
    void orbit(double dxPixels, double dyPixels);
    // Positive steps move towards the pivot.
    void dolly(double steps);
    void reset();
    glm::mat4 view() const;
    float yawDegrees() const { return m_yaw; }
    float pitchDegrees() const { return m_pitch; }
    float distanceScale() const { return m_distance; }

    static constexpr float kDegreesPerPixel = 0.3f;
    static constexpr float kMaxPitch = 85.0f; // short of the pole, where yaw and pitch axes meet
    // The camera's far plane is fixed from the scene bounds: do not dolly out past it.
    static constexpr float kMinDistance = 0.1f, kMaxDistance = 3.0f;
    static constexpr float kDollyPerStep = 0.9f;

  private:
    glm::mat4 m_baseView;
    glm::vec3 m_pivot;
    float m_yaw = 0.0f, m_pitch = 0.0f, m_distance = 1.0f;
};

inline constexpr float kMinExposureEv = -8.0f, kMaxExposureEv = 8.0f;

// Against the per-sample reference at the same n: off, split (left the method, right the
// reference) or difference (|method - reference| x gain over the whole frame).
enum class Compare { Off, Split, Difference };
inline constexpr const char* kCompareNames[] = {"off", "split", "difference"};
inline constexpr float kMaxDifferenceGain = 64.0f;

struct ViewerSettings {
    size_t method = 0; // index into knownMethods()
    uint32_t samples = 8;
    uint32_t aggregates = 2;
    size_t debugView = 0; // 0 = none, else knownMethods()[method].debugViews[debugView - 1]
    // Every other method setting (agaa/method_settings.h: agaa-render's flags); a frame takes
    // those its method reads, the panel lists them all.
    MethodSettings methodSettings;
    float exposureEv = 0.0f; // exposure = 2^exposureEv, on top of the scene's 1.0
    Compare compare = Compare::Off;
    float splitFraction = 0.5f;
    float differenceGain = 4.0f; // Compare::Difference: |method - reference| x gain
    uint32_t pixelSize = 1;      // 1, 2 or 4 swapchain pixels per rendered pixel (1 = 1:1)
};

// Throws std::invalid_argument naming the option when a setting is out of range.
void validate(const ViewerSettings& settings);

class Controls {
  public:
    Controls(const eng::scene::Scene& scene, const ViewerSettings& initial);

    // Applies one frame's input. Returns a line describing a settings change ("" if none).
    std::string apply(const InputEvents& input);
    bool quitRequested() const { return m_quit; }
    // P was pressed since the last call: save the next presented frame.
    bool takeScreenshotRequest() { return std::exchange(m_screenshot, false); }

    // The renderer refused the current settings (e.g. a capability the device lacks): go back
    // to the last settings that rendered. accept() marks the current ones as such.
    void revert() { m_settings = m_accepted; }
    void accept() { m_accepted = m_settings; }

    const ViewerSettings& settings() const { return m_settings; }
    // The UI edits the settings in place; validate() runs when the frame is requested.
    ViewerSettings& settings() { return m_settings; }
    const OrbitCamera& camera() const { return m_camera; }
    // The UI's reset button: the same as key R.
    void reset();
    RenderRequest request(uint32_t width, uint32_t height) const;
    // "agaa n=8 c=2 debug=aggregates": the method and the settings that matter for it.
    std::string describe(uint32_t renderedSamples) const;

    static std::string help();

  private:
    ViewerSettings m_settings, m_accepted, m_initial;
    OrbitCamera m_camera;
    bool m_quit = false;
    bool m_screenshot = false;
};

} // namespace agaa::viewer
