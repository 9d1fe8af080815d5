#include "god_finger/devices/hand_device.h"

#include <cmath>

namespace god_finger
{
namespace
{
// The hand's readings, shared by its fingers: read once per update() time.
struct SharedHand
{
  std::shared_ptr<HandSource> source;
  std::vector<DeviceReading> readings;  // one per finger, sized at construction
  double read_time = NAN;               // the time of the last read (NaN: none yet)
  bool started = false;

  const DeviceReading& at(double time, std::size_t finger)
  {
    if (!(time == read_time))
    {
      source->read(time, &readings);
      read_time = time;
    }
    return readings[finger];
  }
};

class HandFinger : public HapticDevice
{
 public:
  HandFinger(std::shared_ptr<SharedHand> hand, std::size_t index, std::string name)
      : hand_(std::move(hand)), index_(index), name_(std::move(name))
  {
  }
  std::string name() const override
  {
    return hand_->source->name() + "/" + name_;
  }
  void start() override
  {
    if (!hand_->started)
    {
      hand_->source->start();
      hand_->started = true;
    }
  }
  // The force is dropped: a hand source renders none.
  DeviceReading update(double time, const Eigen::Vector3d& /*force*/) override
  {
    return hand_->at(time, index_);
  }
  void setScriptStart(double time) override
  {
    hand_->source->setScriptStart(time);
  }

 private:
  std::shared_ptr<SharedHand> hand_;
  std::size_t index_;
  std::string name_;
};

class HandDevice : public HapticDevice
{
 public:
  explicit HandDevice(std::shared_ptr<HandSource> source) : source_(std::move(source)) {}
  std::string name() const override
  {
    return source_->name();
  }
  void start() override
  {
    throw DeviceError("device '" + source_->name() +
                      "' is a hand (one interface per finger): only the servo loop runs hands; use topology:=servo");
  }
  DeviceReading update(double /*time*/, const Eigen::Vector3d& /*force*/) override
  {
    throw DeviceError("device '" + source_->name() + "' is a hand: run its fingers(), not the hand");
  }
  void setScriptStart(double time) override
  {
    source_->setScriptStart(time);
  }
  std::vector<DeviceFinger> fingers() override
  {
    auto shared = std::make_shared<SharedHand>();
    shared->source = source_;
    const std::vector<std::string> names = source_->fingers();
    shared->readings.resize(names.size());
    std::vector<DeviceFinger> fingers;
    for (std::size_t i = 0; i < names.size(); ++i)
    {
      fingers.push_back({names[i], std::make_unique<HandFinger>(shared, i, names[i])});
    }
    return fingers;
  }

 private:
  std::shared_ptr<HandSource> source_;
};
}  // namespace

std::unique_ptr<HapticDevice> makeHandDevice(std::shared_ptr<HandSource> source)
{
  return std::make_unique<HandDevice>(std::move(source));
}
}  // namespace god_finger
