#include "samples/viewer/ui_panel.h"

#include "agaa/method_settings.h"
#include "agaa/methods.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace agaa::viewer {

namespace {

constexpr size_t kListedPasses = 6;

// Distinct hues for the passes of the timing graph, stable per pass index.
ImU32 passColour(size_t pass) {
    const float hue = std::fmod(float(pass) * 0.618034f, 1.0f);
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(hue, 0.65f, 0.9f, r, g, b);
    return ImGui::GetColorU32(ImVec4(r, g, b, 1.0f));
}

void swatch(ImVec4 colour, const char* text) {
    ImGui::ColorButton(text, colour, ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                       ImVec2(12, 12));
    ImGui::SameLine();
    ImGui::TextWrapped("%s", text);
}

// Every method setting but n, c and the debug view (their own controls above), from its one
// declaration (agaa/method_settings.h): a combo for a choice, a text field for a number (Enter
// applies it; a refused value shows why). Settings the method does not read are greyed out.
void methodSettingsSection(MethodSettings& settings, const std::string& method) {
    if (!ImGui::TreeNode("method settings")) return;
    static std::string refusal;
    for (const MethodOption& option : methodOptions()) {
        if (option.name == "samples" || option.name == "aggregates" || option.name == "debug") continue;
        ImGui::BeginDisabled(!methodReadsOption(option, method));
        const std::string current = option.get(settings);
        if (option.kind == MethodOption::Kind::Choice) {
            if (ImGui::BeginCombo(option.name.c_str(), current.c_str())) {
                for (const std::string& choice : option.choices)
                    if (ImGui::Selectable(choice.c_str(), choice == current)) option.set(settings, choice);
                ImGui::EndCombo();
            }
        } else {
            char text[32];
            std::snprintf(text, sizeof text, "%s", current.c_str());
            if (ImGui::InputText(option.name.c_str(), text, sizeof text,
                                 ImGuiInputTextFlags_EnterReturnsTrue)) {
                try {
                    setMethodOption(settings, option, text);
                    refusal.clear();
                } catch (const std::invalid_argument& e) {
                    refusal = e.what();
                }
            }
        }
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s (%s; default %s)", option.doc.c_str(), option.methods.c_str(),
                              option.defaultText.c_str());
    }
    if (!refusal.empty()) ImGui::TextWrapped("%s", refusal.c_str());
    ImGui::TreePop();
}

void settingsSection(Controls& controls, PanelActions& actions) {
    ViewerSettings& s = controls.settings();
    const auto& methods = knownMethods();
    if (ImGui::BeginCombo("method", methods[s.method].name.c_str())) {
        for (size_t m = 0; m < methods.size(); ++m)
            if (ImGui::Selectable(methods[m].name.c_str(), s.method == m) && s.method != m) {
                s.method = m;
                s.debugView = 0; // debug views belong to one method
            }
        ImGui::EndCombo();
    }
    const MethodInfo& method = methods[s.method];
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", method.summary.c_str());

    ImGui::BeginDisabled(!method.usesSamples);
    const std::string n = std::to_string(s.samples);
    if (ImGui::BeginCombo("n samples", n.c_str())) {
        for (uint32_t v : kSampleCycle)
            if (ImGui::Selectable(std::to_string(v).c_str(), s.samples == v)) s.samples = v;
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();

    ImGui::BeginDisabled(!method.usesAggregates);
    int c = int(s.aggregates);
    if (ImGui::SliderInt("c aggregates", &c, 1, int(kMaxAggregates))) s.aggregates = uint32_t(c);
    ImGui::EndDisabled();

    const char* debugName = s.debugView ? method.debugViews[s.debugView - 1].c_str() : "off";
    ImGui::BeginDisabled(method.debugViews.empty());
    if (ImGui::BeginCombo("debug view", debugName)) {
        if (ImGui::Selectable("off", s.debugView == 0)) s.debugView = 0;
        for (size_t v = 0; v < method.debugViews.size(); ++v)
            if (ImGui::Selectable(method.debugViews[v].c_str(), s.debugView == v + 1)) s.debugView = v + 1;
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();

    ImGui::SliderFloat("exposure EV", &s.exposureEv, kMinExposureEv, kMaxExposureEv, "%+.1f");
    int pixelSize = s.pixelSize == 4 ? 2 : int(s.pixelSize) - 1;
    if (ImGui::Combo("pixel size", &pixelSize,
                     "1:1\0"
                     "2x2\0"
                     "4x4\0"))
        s.pixelSize = 1u << pixelSize;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "swapchain pixels per rendered pixel: larger renders fewer pixels, each an exact block");
    int compare = int(s.compare);
    if (ImGui::Combo("vs reference", &compare, "off\0split\0difference\0")) s.compare = Compare(compare);
    if (s.compare == Compare::Split) ImGui::SliderFloat("split at", &s.splitFraction, 0.05f, 0.95f, "%.2f");
    if (s.compare == Compare::Difference)
        ImGui::SliderFloat("gain", &s.differenceGain, 1.0f, kMaxDifferenceGain, "x%.0f",
                           ImGuiSliderFlags_Logarithmic);

    methodSettingsSection(s.methodSettings, method.name);
    if (ImGui::Button("reset (R)")) actions.reset = true;
    ImGui::SameLine();
    if (ImGui::Button("screenshot (P)")) actions.screenshot = true;
}

void timingSection(const TimingHistory& timings) {
    const double maxMs = std::max(1.0, timings.maxFrameMs());
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 48.0f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                        ImGui::GetColorU32(ImGuiCol_FrameBg));
    const float barWidth = size.x / float(timings.capacity());
    // One stacked bar per frame, newest on the right; height proportional to ms.
    for (size_t f = 0; f < timings.frames(); ++f) {
        const float x0 = origin.x + size.x - float(timings.frames() - f) * barWidth;
        float y = origin.y + size.y;
        for (size_t p = 0; p < timings.passNames().size(); ++p) {
            const float height = float(timings.passMs(f, p) / maxMs) * size.y;
            if (height <= 0.0f) continue;
            draw->AddRectFilled(ImVec2(x0, y - height), ImVec2(x0 + std::max(1.0f, barWidth), y),
                                passColour(p));
            y -= height;
        }
    }
    char scale[48];
    std::snprintf(scale, sizeof scale, "%.0f ms", maxMs);
    draw->AddText(ImVec2(origin.x + 2, origin.y), ImGui::GetColorU32(ImGuiCol_Text), scale);
    ImGui::Dummy(size);
    // The newest frame's slowest passes, two to a row; all of them in the graph's tooltip.
    std::vector<size_t> passes;
    for (size_t p = 0; p < timings.passNames().size(); ++p)
        if (timings.latestMs(p) > 0.0) passes.push_back(p); // in the newest frame (not another method's)
    std::sort(passes.begin(), passes.end(),
              [&](size_t a, size_t b) { return timings.latestMs(a) > timings.latestMs(b); });
    auto entry = [&](size_t p) {
        ImGui::ColorButton(timings.passNames()[p].c_str(), ImGui::ColorConvertU32ToFloat4(passColour(p)),
                           ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(9, 9));
        ImGui::SameLine();
        ImGui::Text("%.1f %s", timings.latestMs(p), timings.passNames()[p].c_str());
    };
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        for (size_t p : passes)
            entry(p);
        ImGui::EndTooltip();
    }
    if (ImGui::BeginTable("passes", 2)) {
        for (size_t i = 0; i < std::min<size_t>(passes.size(), kListedPasses); ++i) {
            ImGui::TableNextColumn();
            entry(passes[i]);
        }
        ImGui::EndTable();
    }
    if (passes.size() > kListedPasses)
        ImGui::TextDisabled("+%zu faster passes (hover the graph)", passes.size() - kListedPasses);
}

void statsSection(const PanelStats& stats) {
    if (!stats.frame) {
        ImGui::Text("%ux%u", stats.width, stats.height);
        return;
    }
    ImGui::Text("%ux%u %s | %.2f fps | GPU %.1f ms", stats.renderWidth, stats.renderHeight,
                stats.renderWidth == stats.width ? "1:1" : "(blocks)", stats.fps,
                stats.frame->timing.frameMs);
    ImGui::Text("n = %u rendered | %s shading events/px", stats.frame->samples,
                stats.eventsPerPixel ? std::to_string(*stats.eventsPerPixel).substr(0, 4).c_str() : "-");
    std::string split;
    for (const auto& [part, bpp] : stats.frame->bytesPerPixelSplit) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%s%s %.1f", split.empty() ? "" : ", ", part.c_str(), bpp);
        split += buffer;
    }
    ImGui::Text("storage %.1f B/px%s%s", stats.frame->bytesPerPixel, split.empty() ? "" : ": ",
                split.c_str());
}

void legendSection(const Controls& controls) {
    const ViewerSettings& s = controls.settings();
    const MethodInfo& method = knownMethods()[s.method];
    if (s.compare == Compare::Difference)
        ImGui::TextWrapped("difference: |%s - reference at n = %u| x %.0f per channel, black = equal",
                           method.name.c_str(), s.samples, s.differenceGain);
    if (s.compare == Compare::Split)
        ImGui::TextWrapped("split: left %s, right the per-sample reference at n = %u", method.name.c_str(),
                           s.samples);
    if (!s.debugView) return;
    const std::string& view = method.debugViews[s.debugView - 1];
    if (view == "aggregates") {
        // shaders/glsl/agaa/debug_aggregates.comp kCountColour
        ImGui::TextUnformatted("aggregates per pixel (hue):");
        swatch(ImVec4(0.25f, 0.25f, 0.25f, 1), "sky / no sample");
        swatch(ImVec4(0.1f, 0.8f, 0.2f, 1), "1 aggregate");
        swatch(ImVec4(0.95f, 0.85f, 0.1f, 1), "2 aggregates");
        swatch(ImVec4(1.0f, 0.5f, 0.05f, 1), "3 aggregates");
        swatch(ImVec4(0.9f, 0.1f, 0.1f, 1), "4 aggregates");
        ImGui::TextWrapped("brightness: share of covered samples in aggregate 0");
    } else if (view == "complex") {
        // shaders/glsl/simple_complex/lighting.comp complexHighlight
        swatch(ImVec4(1.0f, 0.1f, 0.05f, 1), "complex pixel: every sample lit");
        swatch(ImVec4(0.6f, 0.6f, 0.6f, 1), "simple pixel: sample 0 only (grey luma)");
    } else {
        ImGui::Text("debug view %s", view.c_str());
    }
}

} // namespace

PanelActions drawPanel(Controls& controls, const TimingHistory& timings, const PanelStats& stats) {
    PanelActions actions;
    constexpr ImGuiWindowFlags kFixed =
        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings;
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, float(stats.height)), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("settings", nullptr, kFixed);
    ImGui::PushItemWidth(120.0f);
    settingsSection(controls, actions);
    ImGui::PopItemWidth();
    if (!stats.error.empty()) ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "%s", stats.error.c_str());
    ImGui::Separator();
    legendSection(controls);
    ImGui::End();

    // Timings and stats: bottom right, over the scene, collapsible by its title bar.
    const float width = std::max(160.0f, std::min(kTimingWidth, float(stats.width) - kPanelWidth));
    ImGui::SetNextWindowPos(ImVec2(float(stats.width) - width, float(stats.height) - kTimingHeight),
                            ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, kTimingHeight), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("GPU time per pass, last frames", nullptr, kFixed);
    statsSection(stats);
    timingSection(timings);
    ImGui::End();

    if (controls.settings().compare == Compare::Split) {
        // The split line, over the scene.
        const float x = std::round(controls.settings().splitFraction * float(stats.width));
        ImGui::GetForegroundDrawList()->AddLine(ImVec2(x, 0), ImVec2(x, float(stats.height)),
                                                IM_COL32(255, 255, 255, 200), 1.0f);
    }
    return actions;
}

} // namespace agaa::viewer
