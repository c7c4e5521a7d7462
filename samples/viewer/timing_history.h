#pragma once
// The GPU time of every pass over the last frames, for the UI's stacked timing graph. Passes are
// keyed by name in first-seen order, so a method change keeps the colours of passes it shares
// and a pass missing from a frame counts 0 ms there. Pure data: no ImGui, no device.

#include "engine/frame/frame_runner.h"

#include <cstddef>
#include <string>
#include <vector>

namespace agaa::viewer {

class TimingHistory {
  public:
    explicit TimingHistory(size_t capacity = 60) : m_capacity(capacity) {}

    void add(const eng::frame::FrameTiming& timing);
    void clear();

    size_t frames() const { return m_frames.size(); }
    size_t capacity() const { return m_capacity; }
    const std::vector<std::string>& passNames() const { return m_names; }
    // ms of pass `pass` (index into passNames()) in frame `frame` (0 = oldest kept).
    double passMs(size_t frame, size_t pass) const;
    double frameMs(size_t frame) const { return m_frames[frame].totalMs; }
    double maxFrameMs() const;
    // The newest frame's ms of each pass (0 where it did not run).
    double latestMs(size_t pass) const { return m_frames.empty() ? 0.0 : passMs(m_frames.size() - 1, pass); }

  private:
    struct Frame {
        std::vector<double> ms; // by pass index; shorter when later passes were first seen later
        double totalMs = 0.0;   // first pass start to last pass end
    };
    size_t m_capacity;
    std::vector<std::string> m_names;
    std::vector<Frame> m_frames; // oldest first; capacity is small, erase at the front is fine
};

} // namespace agaa::viewer
