// The channel's energy packets as the nodes send them (god_finger/PortEnergy,
// src/ros/channel_port.h): a port's counts go out and come back as the packet they were, with
// their session; a malformed message (a non-finite or negative energy) is refused whole.
#include "channel_port.h"

#include <gtest/gtest.h>

#include <limits>

namespace god_finger
{
namespace
{
PortEnergyObserver counted()
{
  PortEnergyObserver observer;
  observer.observe(0.125, 1.0);
  observer.observe(-0.5, 1.0);
  return observer;
}

TEST(ChannelPortMessages, APortsCountComesBackAsThePacketItWas)
{
  const god_finger::PortEnergy message = portEnergyMessage(ros::Time(12.5), ros::Time(3.25), counted());
  EXPECT_EQ(message.energy_in, 0.125);
  EXPECT_EQ(message.energy_out, 0.5);
  EXPECT_EQ(message.header.frame_id, "world");
  EnergyPacket packet;
  double session = 0.0;
  ASSERT_TRUE(energyPacket(message, &packet, &session));
  EXPECT_EQ(packet.stamp, 12.5);
  EXPECT_EQ(packet.energy_in, 0.125);
  EXPECT_EQ(session, 3.25);
}

TEST(ChannelPortMessages, AMalformedPacketIsRefusedWhole)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  for (const auto& [in, out] :
       {std::pair<double, double>{nan, 0.0}, {0.0, nan}, {infinity, 0.0}, {0.0, -infinity}, {-1e-9, 0.0}, {0.0, -0.1}})
  {
    god_finger::PortEnergy message = portEnergyMessage(ros::Time(1.0), ros::Time(0.5), counted());
    message.energy_in = in;
    message.energy_out = out;
    EnergyPacket packet{7.0, 0.75};
    double session = 9.0;
    EXPECT_FALSE(energyPacket(message, &packet, &session)) << in << " " << out;
    EXPECT_EQ(packet.stamp, 7.0);  // untouched
    EXPECT_EQ(packet.energy_in, 0.75);
    EXPECT_EQ(session, 9.0);
  }
}
}  // namespace
}  // namespace god_finger
