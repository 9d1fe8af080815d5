// rostest: a scenario launch reaches the offline experiment's outcome. Watches the object's TF
// (world -> ~object) for ~duration seconds and checks ~expect:
//   rolls / slides   (slide: rotation angle against translation / radius, as rolling_ratio)
//   held / dropped   (lifts: height above the start at the end, tilt)
//   still / swings   (pinch: rotation about the cylinder's axis after ~after seconds)
// The numbers are printed, beside those god_finger_experiment gives for the same script.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Geometry>
#include <cstdio>

namespace
{
Eigen::Isometry3d toEigen(const geometry_msgs::TransformStamped& t)
{
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() =
      Eigen::Vector3d(t.transform.translation.x, t.transform.translation.y, t.transform.translation.z);
  result.linear() =
      Eigen::Quaterniond(t.transform.rotation.w, t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z)
          .toRotationMatrix();
  return result;
}

TEST(Scenario, ReachesTheOfflineOutcome)
{
  ros::NodeHandle pnh("~");
  const std::string object = pnh.param<std::string>("object", "ball");
  const std::string expect = pnh.param<std::string>("expect", "");
  const double duration = pnh.param("duration", 5.0);
  const double after = pnh.param("after", 0.0);
  const double radius = pnh.param("radius", 0.04);
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);

  Eigen::Isometry3d start;
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (true)
  {
    try
    {
      start = toEigen(buffer.lookupTransform("world", object, ros::Time(0)));
      break;
    }
    catch (const tf2::TransformException&)
    {
      ASSERT_LT(ros::WallTime::now(), give_up) << "no TF world -> " << object;
      ros::WallDuration(0.01).sleep();
    }
  }
  const ros::WallTime t0 = ros::WallTime::now();
  Eigen::Isometry3d pose = start;
  Eigen::Matrix3d after_pose = start.linear();
  bool have_after = false;
  double max_tilt = 0.0;
  double max_turn_about_axis = 0.0;
  while ((ros::WallTime::now() - t0).toSec() < duration)
  {
    ros::WallDuration(0.005).sleep();
    pose = toEigen(buffer.lookupTransform("world", object, ros::Time(0)));
    max_tilt = std::max(max_tilt, std::acos(std::min(1.0, pose.linear()(2, 2))));
    if ((ros::WallTime::now() - t0).toSec() >= after)
    {
      if (!have_after)
      {
        after_pose = pose.linear();
        have_after = true;
      }
      const Eigen::AngleAxisd turn(pose.linear() * after_pose.transpose());
      max_turn_about_axis =
          std::max(max_turn_about_axis, turn.angle() * std::abs(turn.axis().dot(pose.linear().col(0))));
    }
  }
  const Eigen::Vector3d moved = pose.translation() - start.translation();
  const double translation = std::hypot(moved.x(), moved.y());
  const double rotation = Eigen::AngleAxisd(pose.linear() * start.linear().transpose()).angle();
  const double height = moved.z();
  const double final_tilt = std::acos(std::min(1.0, pose.linear()(2, 2)));
  char line[400];
  std::snprintf(line, sizeof(line),
                "%s (expect %s): translation %.4f m, rotation %.3f rad (ratio %.2f), height %.4f m, max tilt %.3f rad, "
                "final tilt %.3f rad, "
                "max turn about the axis after %.1f s %.4f rad",
                ros::this_node::getName().c_str(), expect.c_str(), translation, rotation,
                translation > 0 ? rotation * radius / translation : 0.0, height, max_tilt, final_tilt, after,
                max_turn_about_axis);
  std::printf("%s\n", line);
  std::fflush(stdout);
  RecordProperty("measured", line);
  if (expect == "rolls")
  {
    EXPECT_GT(translation, 0.04);
    EXPECT_GT(rotation * radius / translation, 0.8);
  }
  else if (expect == "slides")
  {
    EXPECT_GT(translation, 0.08);
    EXPECT_LT(rotation * radius / translation, 0.25);
  }
  else if (expect == "held")
  {
    // Held level: at the end of the hold the plate is within 0.05 rad of level (offline: 0.002
    // and 0.006 rad). While lifting, a device thread stalled by the loaded 2-core machine lags
    // its finger for a few tens of ms and the plate tips transiently (seen up to 0.087 rad over
    // 2.4 cm between fingers, also before the pose-triggered physics loop; 0.006-0.011 rad
    // otherwise), then comes back level: the bound on the maximum is the one that separates
    // held from tipped (god-objects tip 1.0-1.2 rad).
    EXPECT_NEAR(height, 0.1, 0.01);
    EXPECT_LT(final_tilt, 0.05);
    EXPECT_LT(max_tilt, 0.3);
  }
  else if (expect == "dropped")
  {
    EXPECT_LT(height, 0.05);
  }
  else if (expect == "still")
  {
    EXPECT_GT(height, 0.08);
    EXPECT_LT(max_turn_about_axis, 0.02);
  }
  else if (expect == "swings")
  {
    EXPECT_GT(max_turn_about_axis, 1.0);
  }
  else
  {
    FAIL() << "unknown ~expect '" << expect << "'";
  }
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "scenario_test");
  return RUN_ALL_TESTS();
}
