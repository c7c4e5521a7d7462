#include "samples/viewer/timing_history.h"

#include <algorithm>

namespace agaa::viewer {

void TimingHistory::add(const eng::frame::FrameTiming& timing) {
    Frame frame;
    frame.totalMs = timing.frameMs;
    for (const eng::frame::PassTiming& p : timing.passes) {
        auto it = std::find(m_names.begin(), m_names.end(), p.name);
        const size_t index = size_t(it - m_names.begin());
        if (it == m_names.end()) m_names.push_back(p.name);
        if (frame.ms.size() <= index) frame.ms.resize(index + 1, 0.0);
        frame.ms[index] += p.gpuMs;
    }
    m_frames.push_back(std::move(frame));
    if (m_frames.size() > m_capacity) m_frames.erase(m_frames.begin());
}

void TimingHistory::clear() {
    m_frames.clear();
    m_names.clear();
}

double TimingHistory::passMs(size_t frame, size_t pass) const {
    const Frame& f = m_frames[frame];
    return pass < f.ms.size() ? f.ms[pass] : 0.0;
}

double TimingHistory::maxFrameMs() const {
    double m = 0.0;
    for (const Frame& f : m_frames) {
        double sum = 0.0;
        for (double ms : f.ms)
            sum += ms;
        m = std::max({m, f.totalMs, sum});
    }
    return m;
}

} // namespace agaa::viewer
