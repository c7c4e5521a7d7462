// The timing graph's data (timing_history.h): passes keyed by name across method changes, the
// window of the last frames, and the graph's scale.

#include "samples/viewer/timing_history.h"

#include <gtest/gtest.h>

namespace {

using agaa::viewer::TimingHistory;
using eng::frame::FrameTiming;

FrameTiming frame(std::vector<eng::frame::PassTiming> passes, double total) {
    FrameTiming t;
    t.passes = std::move(passes);
    t.frameMs = total;
    return t;
}

TEST(ViewerTimingHistory, PassesKeepTheirIndexAcrossMethodChanges) {
    TimingHistory h(8);
    h.add(frame({{"agaa.gbuffer", 2.0}, {"viewer.display", 1.0}}, 3.5));
    h.add(frame({{"noaa.lighting", 5.0}, {"viewer.display", 1.5}}, 7.0));
    ASSERT_EQ(h.passNames(), (std::vector<std::string>{"agaa.gbuffer", "viewer.display", "noaa.lighting"}));
    EXPECT_DOUBLE_EQ(h.passMs(0, 0), 2.0);
    EXPECT_DOUBLE_EQ(h.passMs(0, 2), 0.0) << "a pass first seen later is 0 ms in older frames";
    EXPECT_DOUBLE_EQ(h.passMs(1, 0), 0.0) << "a pass missing from a frame is 0 ms there";
    EXPECT_DOUBLE_EQ(h.passMs(1, 1), 1.5);
    EXPECT_DOUBLE_EQ(h.latestMs(2), 5.0);
    EXPECT_DOUBLE_EQ(h.frameMs(1), 7.0);
}

TEST(ViewerTimingHistory, KeepsOnlyTheLastFrames) {
    TimingHistory h(3);
    for (int i = 1; i <= 5; ++i)
        h.add(frame({{"p", double(i)}}, double(i)));
    ASSERT_EQ(h.frames(), 3u);
    EXPECT_DOUBLE_EQ(h.passMs(0, 0), 3.0) << "the oldest kept is frame 3 of 5";
    EXPECT_DOUBLE_EQ(h.latestMs(0), 5.0);
}

TEST(ViewerTimingHistory, ScaleCoversTheStackedPasses) {
    // The graph stacks pass times; their sum can exceed the first-to-last span when passes
    // overlap or the span is short, and the bars must still fit.
    TimingHistory h(4);
    h.add(frame({{"a", 4.0}, {"b", 3.0}}, 6.0));
    h.add(frame({{"a", 1.0}}, 9.0));
    EXPECT_DOUBLE_EQ(h.maxFrameMs(), 9.0);
    h.add(frame({{"a", 8.0}, {"b", 3.0}}, 10.0));
    EXPECT_DOUBLE_EQ(h.maxFrameMs(), 11.0);
    h.clear();
    EXPECT_EQ(h.frames(), 0u);
    EXPECT_TRUE(h.passNames().empty());
    EXPECT_DOUBLE_EQ(h.latestMs(0), 0.0);
}

} // namespace
