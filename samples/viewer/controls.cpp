#include "samples/viewer/controls.h"

#include "agaa/method_settings.h"
#include "agaa/methods.h"
#include "engine/frame/frame_constants.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace agaa::viewer {

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
    // Dragging right turns the scene right; dragging down lifts the camera over it.
    m_yaw = std::remainder(m_yaw + float(dxPixels) * kDegreesPerPixel, 360.0f);
    m_pitch = std::clamp(m_pitch + float(dyPixels) * kDegreesPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::dolly(double steps) {
    m_distance = std::clamp(m_distance * std::pow(kDollyPerStep, float(steps)), kMinDistance, kMaxDistance);
}

void OrbitCamera::reset() {
    m_yaw = 0.0f;
    m_pitch = 0.0f;
    m_distance = 1.0f;
}

glm::mat4 OrbitCamera::view() const {
    const glm::mat4 yawed = eng::frame::orbitView(m_baseView, m_pivot, m_yaw);
    // The pivot in view space; pitch rotates about the view X axis through it, and the dolly
    // scales its distance from the eye. Both keep the pivot on the same view ray.
    const glm::vec3 pivot = glm::vec3(yawed * glm::vec4(m_pivot, 1.0f));
    glm::mat4 pitch = glm::translate(glm::mat4(1.0f), pivot) *
                      glm::rotate(glm::mat4(1.0f), glm::radians(m_pitch), glm::vec3(1.0f, 0.0f, 0.0f)) *
                      glm::translate(glm::mat4(1.0f), -pivot);
    glm::mat4 dolly = glm::translate(glm::mat4(1.0f), pivot * (m_distance - 1.0f));
    return dolly * pitch * yawed;
}

void validate(const ViewerSettings& s) {
    const auto& methods = knownMethods();
    if (s.method >= methods.size()) throw std::invalid_argument("method index out of range");
    if (std::find(std::begin(kSampleCycle), std::end(kSampleCycle), s.samples) == std::end(kSampleCycle))
        throw std::invalid_argument("--samples " + std::to_string(s.samples) +
                                    " is not one the viewer cycles through (allowed: 4, 8, 16, 32)");
    if (s.aggregates < 1 || s.aggregates > kMaxAggregates)
        throw std::invalid_argument("--aggregates " + std::to_string(s.aggregates) +
                                    " is out of range (1..4)");
    if (s.debugView > methods[s.method].debugViews.size())
        throw std::invalid_argument("debug view index out of range for " + methods[s.method].name);
    if (!(s.exposureEv >= kMinExposureEv && s.exposureEv <= kMaxExposureEv))
        throw std::invalid_argument("--exposure-ev " + std::to_string(s.exposureEv) +
                                    " is out of range (-8..8)");
    if (!(s.differenceGain >= 1.0f && s.differenceGain <= kMaxDifferenceGain))
        throw std::invalid_argument("--difference-gain " + std::to_string(s.differenceGain) +
                                    " is out of range (1..64)");
    if (s.pixelSize != 1 && s.pixelSize != 2 && s.pixelSize != 4)
        throw std::invalid_argument("--pixel-size " + std::to_string(s.pixelSize) +
                                    " is not allowed (allowed: 1, 2, 4)");
    if (!(s.splitFraction > 0.0f && s.splitFraction < 1.0f))
        throw std::invalid_argument("split position " + std::to_string(s.splitFraction) +
                                    " is out of range (0, 1)");
    validate(s.methodSettings.effects);
}

namespace {

glm::vec3 boundsCentre(const eng::scene::Scene& scene) {
    return 0.5f * (scene.bounds.min + scene.bounds.max);
}

} // namespace

Controls::Controls(const eng::scene::Scene& scene, const ViewerSettings& initial)
    : m_settings(initial), m_accepted(initial), m_initial(initial),
      m_camera(scene.cameras.at(0).view, boundsCentre(scene)) {
    validate(initial);
}

std::string Controls::apply(const InputEvents& input) {
    if (input.dragX != 0.0 || input.dragY != 0.0) m_camera.orbit(input.dragX, input.dragY);
    if (input.scroll != 0.0) m_camera.dolly(input.scroll);

    const auto& methods = knownMethods();
    std::string lines;
    for (int key : input.keys) {
        std::string changed;
        const MethodInfo& method = methods[m_settings.method];
        if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) {
            const size_t index = size_t(key - GLFW_KEY_1);
            if (index < methods.size()) {
                m_settings.method = index;
                m_settings.debugView = 0; // debug views belong to one method
                changed = "method " + methods[index].name;
            } else {
                changed = "no method on key " + std::to_string(index + 1) + " (" +
                          std::to_string(methods.size()) + " methods)";
            }
        } else if (key == GLFW_KEY_S) {
            auto it = std::find(std::begin(kSampleCycle), std::end(kSampleCycle), m_settings.samples);
            it = (it == std::end(kSampleCycle) || it + 1 == std::end(kSampleCycle)) ? std::begin(kSampleCycle)
                                                                                    : it + 1;
            m_settings.samples = *it;
            changed = "samples n=" + std::to_string(m_settings.samples) +
                      (method.usesSamples ? "" : " (" + method.name + " renders 1 sample)");
        } else if (key == GLFW_KEY_A) {
            m_settings.aggregates = m_settings.aggregates % kMaxAggregates + 1;
            changed = "aggregates c=" + std::to_string(m_settings.aggregates) +
                      (method.usesAggregates ? "" : " (" + method.name + " has no aggregates)");
        } else if (key == GLFW_KEY_D) {
            if (method.debugViews.empty()) {
                changed = method.name + " has no debug views";
            } else {
                m_settings.debugView = (m_settings.debugView + 1) % (method.debugViews.size() + 1);
                changed = "debug view " + (m_settings.debugView ? method.debugViews[m_settings.debugView - 1]
                                                                : std::string("off"));
            }
        } else if (key == GLFW_KEY_X) {
            m_settings.compare = Compare((int(m_settings.compare) + 1) % 3);
            changed = std::string("against the reference: ") + kCompareNames[int(m_settings.compare)];
        } else if (key == GLFW_KEY_R) {
            reset();
            changed = "reset camera and settings";
        } else if (key == GLFW_KEY_P) {
            m_screenshot = true;
        } else if (key == GLFW_KEY_H) {
            changed = help();
        } else if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) {
            m_quit = true;
        }
        if (!changed.empty()) lines += (lines.empty() ? "" : "\n") + changed;
    }
    return lines;
}

void Controls::reset() {
    m_camera.reset();
    m_settings = m_initial;
}

RenderRequest Controls::request(uint32_t width, uint32_t height) const {
    const MethodInfo& method = knownMethods()[m_settings.method];
    RenderRequest r;
    r.method = method.name;
    for (const MethodOption& option : methodOptions())
        if (methodReadsOption(option, method.name))
            option.set(r.settings, option.get(m_settings.methodSettings));
    r.settings.samples = m_settings.samples;
    r.settings.aggregates = m_settings.aggregates;
    r.settings.debug = m_settings.debugView ? method.debugViews[m_settings.debugView - 1] : std::string();
    r.view.width = width;
    r.view.height = height;
    r.view.camera = 0;
    r.view.viewOverride = m_camera.view();
    r.view.exposure = std::exp2(m_settings.exposureEv);
    r.warmupFrames = 0;
    r.timedFrames = 1; // interactive: one frame each, the live numbers are that frame's
    return r;
}

std::string Controls::describe(uint32_t renderedSamples) const {
    const MethodInfo& method = knownMethods()[m_settings.method];
    std::string s = method.name + " n=" + std::to_string(renderedSamples);
    if (method.usesAggregates) s += " c=" + std::to_string(m_settings.aggregates);
    if (m_settings.debugView) s += " debug=" + method.debugViews[m_settings.debugView - 1];
    return s;
}

std::string Controls::help() {
    std::string s =
        "controls: left-drag orbit | scroll dolly | S samples (4,8,16,32) | A aggregates (1..4) | "
        "D debug view | X compare (off, split, difference) | R reset | P screenshot | H help | Esc/Q quit "
        "(every setting is also "
        "in "
        "the UI panel)\nmethods:";
    // Every method; keys 1..9 select the first nine, the rest are in the UI panel only.
    const auto& methods = knownMethods();
    for (size_t i = 0; i < methods.size(); ++i)
        s += " " + (i < 9 ? std::to_string(i + 1) + "=" : std::string("(panel)")) + methods[i].name;
    return s;
}

} // namespace agaa::viewer
