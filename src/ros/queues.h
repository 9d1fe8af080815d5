// Queue sizes of the 1 kHz topics.
//  - Publishers keep 100 messages per subscriber: a slow subscriber (rosbag record, rviz, a
//    test) gets every message a little late instead of losing some; a fast one never waits.
//  - Subscribers keep 10: callbacks only store the newest value, and a short queue means a
//    rejected (NaN) message is counted instead of silently overwritten.
#pragma once

namespace god_finger
{
constexpr int kPublisherQueue = 100;
constexpr int kSubscriberQueue = 10;
}  // namespace god_finger
