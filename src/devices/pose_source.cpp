#include "god_finger/devices/pose_source.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/parameter_table.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
class PoseSource : public HandSource
{
 public:
  PoseSource(const PoseSourceParams& params, std::shared_ptr<PoseFeed> feed, std::function<double()> now)
      : params_(params),
        feed_(std::move(feed)),
        now_(std::move(now)),
        last_(params.fingers.size(), params.rest),
        last_orientation_(params.fingers.size())
  {
  }
  std::string name() const override
  {
    return "pose_source";
  }
  std::vector<std::string> fingers() const override
  {
    return params_.fingers;
  }
  void read(double /*time*/, std::vector<DeviceReading>* readings) override
  {
    const std::vector<FingerPose>& poses = feed_->read();
    const double now = now_();
    for (std::size_t i = 0; i < last_.size(); ++i)
    {
      DeviceReading& reading = (*readings)[i];
      const FingerPose& pose = poses[i];
      reading.tracked = pose.stamp >= 0.0 && now - pose.stamp <= params_.pose_timeout;
      reading.missing = !reading.tracked && pose.missing;
      if (reading.tracked)
      {
        last_[i] = pose.position;
        last_orientation_[i] = pose;
      }
      reading.position = last_[i];
      reading.has_orientation = last_orientation_[i].has_orientation;
      reading.orientation = last_orientation_[i].orientation;
      reading.velocity.setZero();  // the loop estimates it from the positions
      reading.buttons = 0;
    }
  }

 private:
  PoseSourceParams params_;
  std::shared_ptr<PoseFeed> feed_;
  std::function<double()> now_;
  std::vector<Eigen::Vector3d> last_;         // m: each finger's last tracked position
  std::vector<FingerPose> last_orientation_;  // each finger's last tracked pose, for its orientation
};
}  // namespace

const ParameterTable<PoseSourceParams>& poseSourceParameterTable()
{
  using P = PoseSourceParams;
  static const ParameterTable<P> table = {
      realRow<P>("poll_rate", "Hz", openClosed(0.0, 10000.0), "how often TF frames are looked up",
                 [](P& p) -> double& { return p.poll_rate; }),
      realRow<P>("pose_timeout", "s", openClosed(0.0, 10.0), "a finger whose newest pose is older lets go",
                 [](P& p) -> double& { return p.pose_timeout; }),
  };
  return table;
}

PoseSourceParams readPoseSourceParams(const ParameterSource& source)
{
  PoseSourceParams params;
  params.fingers = readStringList(source, "fingers", params.fingers);
  if (params.fingers.empty() || params.fingers.size() > 10)
  {
    throw InputError("parameter '" + source.fullName("fingers") + "' must name 1 to 10 fingers (got " +
                     std::to_string(params.fingers.size()) + ")");
  }
  for (std::size_t i = 0; i < params.fingers.size(); ++i)
  {
    const std::string& name = params.fingers[i];
    if (name.empty() || name.find_first_of("/ ") != std::string::npos ||
        std::count(params.fingers.begin(), params.fingers.begin() + i, name) > 0)
    {
      throw InputError("parameter '" + source.fullName("fingers") + "': finger " + std::to_string(i) + " '" + name +
                       "' must be a unique non-empty name without '/' or spaces");
    }
  }
  params.topic = readString(source, "topic", params.topic);
  if (params.topic.empty())
  {
    throw InputError("parameter '" + source.fullName("topic") + "' must name a geometry_msgs/PoseArray topic");
  }
  params.frames = readStringList(source, "frames", params.frames);
  if (!params.frames.empty() && params.frames.size() != params.fingers.size())
  {
    throw InputError("parameter '" + source.fullName("frames") + "' must list one TF frame per finger (" +
                     std::to_string(params.fingers.size()) + "), not " + std::to_string(params.frames.size()));
  }
  params.reference_frame = readString(source, "reference_frame", params.reference_frame);
  readRows(source, poseSourceParameterTable(), &params);
  params.rest = readVector(source, "rest", params.rest);
  return params;
}

void setPoseOrientation(double x, double y, double z, double w, FingerPose* pose)
{
  pose->has_orientation = !(x == 0.0 && y == 0.0 && z == 0.0 && w == 0.0);
  pose->orientation = pose->has_orientation ? Eigen::Quaterniond(w, x, y, z) : Eigen::Quaterniond::Identity();
}

void PoseFeed::write(const std::vector<FingerPose>& poses)
{
  for (std::size_t i = 0; i < latest_.size(); ++i)
  {
    if (i >= poses.size())
    {
      latest_[i].missing = true;
    }
    else if (poses[i].position.allFinite() && std::isfinite(poses[i].stamp))
    {
      latest_[i] = poses[i];
      latest_[i].missing = false;
    }
  }
  box_.back() = latest_;  // same length: no allocation
  box_.publish();
}

const std::vector<FingerPose>& PoseFeed::read()
{
  box_.take();
  return box_.front();
}

std::shared_ptr<HandSource> makePoseSource(const PoseSourceParams& params, std::shared_ptr<PoseFeed> feed,
                                           std::function<double()> now)
{
  if (!feed || feed->fingers() != params.fingers.size())
  {
    throw InputError("backend 'pose_source' needs a pose feed of " + std::to_string(params.fingers.size()) +
                     " fingers, which this program does not give it");
  }
  return std::make_shared<PoseSource>(params, std::move(feed), std::move(now));
}
}  // namespace god_finger
