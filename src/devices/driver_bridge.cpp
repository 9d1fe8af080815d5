#include "god_finger/devices/driver_bridge.h"

#include "god_finger/support/input_error.h"

#include <cerrno>
#include <cmath>
#include <ctime>

namespace god_finger
{
const ParameterTable<DriverBridgeParams>& driverBridgeParameterTable()
{
  using P = DriverBridgeParams;
  static const ParameterTable<P> table = {
      realRow<P>("stale_timeout", "s", openClosed(0.0, 10.0),
                 "a ROS driver whose newest state is older is a device fault (the finger lets go, zero force)",
                 [](P& p) -> double& { return p.stale_timeout; }),
      realRow<P>("state_wait", "s", closed(0.0, 0.01),
                 "the servo loop's tick waits this long for a ROS driver's next state, to answer it at once "
                 "(0: never waits; several drivers in one loop: their sum under the period)",
                 [](P& p) -> double& { return p.state_wait; }),
  };
  return table;
}

DriverBridgeParams readDriverBridgeParams(const std::string& backend, const ParameterSource& source, double max_force)
{
  DriverBridgeParams params;
  params.backend = backend;
  params.max_force = max_force;
  params.driver_ns = readString(source, "driver_ns", "");
  if (params.driver_ns.empty())
  {
    throw InputError("parameter '" + source.fullName("driver_ns") + "' is required by backend '" + backend +
                     "' (the driver's namespace; config/drivers/" + backend + ".yaml sets its default)");
  }
  params.arm = readString(source, "arm", "");
  params.frame = &findVendorFrame(readString(source, "driver_frame", ""), source.fullName("driver_frame"));
  params.position_unit = readDouble(source, "driver_position_unit", 0.0, 0.0, 1e3, "m per driver unit", true);
  params.center = readVector(source, "driver_center", Eigen::Vector3d::Zero());
  readRows(source, driverBridgeParameterTable(), &params);
  return params;
}

DriverLink::DriverLink() : force_(Eigen::Vector3d::Zero())
{
  sem_init(&force_ready_, 0, 0);
  sem_init(&state_ready_, 0, 0);
}

DriverLink::~DriverLink()
{
  connection.reset();  // its sender waits on the semaphore
  sem_destroy(&force_ready_);
  sem_destroy(&state_ready_);
}

void DriverLink::writeState(const Eigen::Vector3d& position, double stamp)
{
  if (!position.allFinite() || !std::isfinite(stamp))
  {
    rejected_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  DriverState& state = state_.back();
  state.position = position;
  state.stamp = stamp;
  state_.publish();
  states_.fetch_add(1, std::memory_order_relaxed);
  sem_post(&state_ready_);
}

void DriverLink::setButtons(std::uint32_t buttons)
{
  buttons_.store(buttons, std::memory_order_relaxed);
}

void DriverLink::setButton(int index, bool pressed)
{
  const std::uint32_t bit = 1u << index;
  if (pressed)
  {
    buttons_.fetch_or(bit, std::memory_order_relaxed);
  }
  else
  {
    buttons_.fetch_and(~bit, std::memory_order_relaxed);
  }
}

const DriverState& DriverLink::read()
{
  state_.take();
  return state_.front();
}

const DriverState& DriverLink::awaitState(double timeout)
{
  while (sem_trywait(&state_ready_) == 0)
  {
  }
  if (!state_.take() && timeout > 0.0)
  {
    timespec wake;
    clock_gettime(CLOCK_MONOTONIC, &wake);
    const long nanoseconds = static_cast<long>(timeout * 1e9);
    wake.tv_nsec += nanoseconds;
    wake.tv_sec += wake.tv_nsec / 1000000000L;
    wake.tv_nsec %= 1000000000L;
    while (sem_clockwait(&state_ready_, CLOCK_MONOTONIC, &wake) != 0 && errno == EINTR)
    {
    }
    state_.take();
  }
  return state_.front();
}

void DriverLink::sendForce(const Eigen::Vector3d& force)
{
  force_.back() = force;
  force_.publish();
  int waiting = 0;
  sem_getvalue(&force_ready_, &waiting);
  if (waiting <= 0)
  {
    sem_post(&force_ready_);
  }
}

bool DriverLink::takeForce(double timeout, Eigen::Vector3d* force)
{
  timespec wake;
  clock_gettime(CLOCK_REALTIME, &wake);
  const long nanoseconds = static_cast<long>(timeout * 1e9);
  wake.tv_sec += nanoseconds / 1000000000L;
  wake.tv_nsec += nanoseconds % 1000000000L;
  if (wake.tv_nsec >= 1000000000L)
  {
    wake.tv_nsec -= 1000000000L;
    ++wake.tv_sec;
  }
  while (sem_timedwait(&force_ready_, &wake) != 0)
  {
    if (errno != EINTR)
    {
      return false;
    }
  }
  if (!force_.take())
  {
    return false;  // a post whose force an earlier take already had
  }
  *force = force_.front();
  return true;
}

DriverBridgeDevice::DriverBridgeDevice(const DriverBridgeParams& params, std::shared_ptr<DriverLink> link,
                                       std::function<double()> now)
    : params_(params), link_(std::move(link)), now_(std::move(now))
{
  if (!link_ || !params_.frame || !now_)
  {
    throw InputError("backend '" + params_.backend + "' needs a driver link, a frame and a clock");
  }
}

DriverBridgeDevice::~DriverBridgeDevice()
{
  link_->sendForce(Eigen::Vector3d::Zero());
}

Eigen::Vector3d DriverBridgeDevice::toDevice(const Eigen::Vector3d& driver_position) const
{
  return params_.frame->toDevice(driver_position - params_.center) * params_.position_unit;
}

Eigen::Vector3d DriverBridgeDevice::forceToDriver(const Eigen::Vector3d& device_force) const
{
  return params_.frame->toVendor(motorCommand(device_force, params_.max_force));
}

DeviceReading DriverBridgeDevice::read(double wait)
{
  const DriverState& state = wait > 0.0 ? link_->awaitState(wait) : link_->read();
  const bool fresh = state.stamp >= 0.0 && now_() - state.stamp <= params_.stale_timeout;
  if (fresh && state.stamp != last_stamp_)
  {
    last_position_ = toDevice(state.position);
    last_velocity_ = velocity_.update(state.stamp, last_position_);
    last_stamp_ = state.stamp;
  }
  DeviceReading reading;
  reading.tracked = fresh;
  reading.position = last_position_;
  reading.velocity = fresh ? last_velocity_ : Eigen::Vector3d::Zero();
  reading.buttons = link_->buttons();
  return reading;
}

void DriverBridgeDevice::send(const DeviceReading& reading, const Eigen::Vector3d& force)
{
  link_->sendForce(reading.tracked ? forceToDriver(force) : Eigen::Vector3d::Zero());
}

DeviceReading DriverBridgeDevice::update(double /*time*/, const Eigen::Vector3d& force)
{
  // The force answers the last reading; a driver stale now gets zero whatever it answered.
  const DeviceReading reading = read(0.0);
  send(reading, force);
  return reading;
}

DeviceReading DriverBridgeDevice::exchangeFrame(double /*time*/, FrameResponder& responder)
{
  const DeviceReading reading = read(params_.state_wait);
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  responder.respond(reading, &force, &torque);
  send(reading, force);
  return reading;
}
}  // namespace god_finger
