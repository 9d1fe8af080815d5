#include "god_finger/scenarios/delay_sweep.h"

#include "god_finger/haptics/passivity_controller.h"
#include "god_finger/haptics/two_port_passivity.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/runtime/delay_line.h"
#include "god_finger/runtime/multirate_render.h"
#include "god_finger/runtime/servo_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>

namespace god_finger
{
namespace
{
constexpr double kTick = 1e-3;     // s
constexpr double kDuration = 4.0;  // s
// The run's last kQuietTail seconds have no tremor (delay_sweep.h): its last second shows what
// the loop does on its own; the 0.5 s before it lets the moving mean (0.2 s) forget the tremor.
constexpr double kQuietTail = 1.5;        // s
constexpr int kHighPassHalfWindow = 100;  // ticks: the moving mean's half window (0.2 s in all)
// Ticks before the tremor stops over which its answer is measured (tremor_hf_rms_N): from 2.1 s,
// after the press's ramp ends at 2 s and the moving mean has left that corner.
constexpr std::size_t kTremorWindow = 400;
constexpr double kBlockMass = 0.05;       // kg: the grasp's block
constexpr double kBlockHalfWidth = 0.02;  // m

struct OperatorModel
{
  double mass;       // kg: handle and hand
  double stiffness;  // N/m: the hand's grip on its rest point
  double damping;    // N s/m
  double tremor;     // m: amplitude of the rest point's tremor
  double tremor_hz;  // Hz
};

OperatorModel operatorModel(DelayOperator op)
{
  return op == DelayOperator::kWorstCase ? OperatorModel{0.1, 300.0, 0.2, 0.0, 0.0}
                                         : OperatorModel{0.15, 300.0, 3.0, 1e-4, 9.0};
}

// The operator's rest point (m) for port `port` at time t (s). Port 0 pushes along +x, port 1
// (the grasp's right finger) along -x.
double restPoint(DelayTask task, int port, double t)
{
  const auto ramp = [](double t, double t0, double t1, double from, double to)
  { return t <= t0 ? from : (t >= t1 ? to : from + (to - from) * (t - t0) / (t1 - t0)); };
  switch (task)
  {
    case DelayTask::kPress:
      return ramp(t, 0.5, 2.0, -0.01, 0.02);
    case DelayTask::kTap:
      for (const double start : {1.0, 2.5})
      {
        const double w = t - start;
        if (w >= 0.0 && w < 0.2)
        {
          return w < 0.05 ? ramp(w, 0.0, 0.05, -0.02, 0.015) : (w < 0.15 ? 0.015 : ramp(w, 0.15, 0.2, 0.015, -0.02));
        }
      }
      return -0.02;
    case DelayTask::kGrasp:
    {
      const double left = ramp(t, 0.5, 1.5, -0.04, -kBlockHalfWidth + 0.015);
      return port == 0 ? left : -left;
    }
    case DelayTask::kFree:
      return 0.03 * std::sin(2.0 * M_PI * t);
  }
  return 0.0;
}

struct Message
{
  double release;  // s
  double stamp;    // s: when it was sent
  double a;        // position (m) or force (N)
  double b;        // velocity (m/s)
  double energy;   // J: the sender's port's E_in as of `stamp` (the two-port's packet)
  // The local coupling's god-object (ros ProxyState; `a` is the proxy): the hand position the
  // step answered (m), its force on the hand (N), and its contact plane's normal along x (+-1;
  // 0: none).
  double target = 0.0;
  double force = 0.0;
  double plane = 0.0;
};

// One direction of the link: messages in flight, the newest delivered.
class Channel
{
 public:
  explicit Channel(const DelayLineParams& params) : schedule_(params) {}
  void send(double now, double a, double b, double energy)
  {
    send(now, Message{0.0, 0.0, a, b, energy});
  }
  void send(double now, Message message)
  {
    const double release = schedule_.release(now);
    if (release >= 0.0)
    {
      message.release = release;
      message.stamp = now;
      flight_.push_back(message);
    }
  }
  // The newest message released by `now`, if any arrived since the last call.
  bool receive(double now, Message* newest)
  {
    bool any = false;
    while (!flight_.empty() && flight_.front().release <= now)
    {
      if (!any || flight_.front().stamp > newest->stamp)
      {
        *newest = flight_.front();
        any = true;
      }
      flight_.pop_front();
    }
    return any;
  }
  long lost() const
  {
    return schedule_.lost();
  }

 private:
  DelaySchedule schedule_;
  std::deque<Message> flight_;
};

struct Port
{
  Port(const DelayLineParams& up_params, const DelayLineParams& down_params, const PassivityParams& one_port,
       const PassivityParams& device_side, const PassivityParams& physics_side)
      : up(up_params),
        down(down_params),
        controller(one_port, kTick),
        device_port(device_side, kTick),
        physics_port(physics_side, kTick)
  {
  }
  Channel up;                                 // positions to the physics
  Channel down;                               // forces back
  PassivityController controller;             // at the device, in either form
  DevicePortPassivity device_port;            // the two-port's device side: observed only
  PhysicsPortPassivity physics_port;          // its physics side: the two-port form's controller
  double max_drift = 0.0;                     // m
  double x = 0.0;                             // m: the handle
  double v = 0.0;                             // m/s
  Message seen{0.0, -1.0, 0.0, 0.0, 0.0};     // at the physics: the newest position
  Message command{0.0, -1.0, 0.0, 0.0, 0.0};  // at the device: the newest force (or god-object)
  MultirateState render;                      // local coupling: the haptic side's renderer
  double previous_x = 0.0;                    // m, m/s: the handle's at the previous tick
  double previous_v = 0.0;
  std::vector<double> rendered;   // N, per tick
  std::vector<double> positions;  // m, per tick
  std::vector<char> pressing;     // per tick: the physics' proxy held by the surface
};

// The local coupling's force on the hand (N along x) this tick, rendered as the haptic node does
// (ros/haptic_node.h: runtime/multirate_render.h against the last god-object that came, lag 1).
// A local coupling's god-object message as the renderer's step (lag 1).
MultirateStep localStep(const Message& message)
{
  MultirateStep step;
  step.proxy_position = Eigen::Vector3d(message.a, 0, 0);
  step.step_target = Eigen::Vector3d(message.target, 0, 0);
  step.user_force = Eigen::Vector3d(message.force, 0, 0);
  step.lag = 1;
  if (message.plane != 0.0)
  {
    step.plane_count = 1;
    step.plane_normals[0] = Eigen::Vector3d(message.plane, 0, 0);
  }
  return step;
}

double localCoupling(const CouplingProfile& coupling, Port& port)
{
  const MultirateStep step = localStep(port.command);
  const MultirateDevice device{Eigen::Vector3d(port.x, 0, 0), Eigen::Vector3d(port.previous_x, 0, 0),
                               Eigen::Vector3d(port.v, 0, 0), Eigen::Vector3d(port.previous_v, 0, 0)};
  renderMultirate(coupling, ServoLoopParams().recovery_periods, device, step, &port.render);
  return port.render.force.x();
}

double rms(const std::vector<double>& values, std::size_t from, std::size_t to)
{
  double sum = 0.0;
  for (std::size_t i = from; i < to; ++i)
  {
    sum += values[i] * values[i];
  }
  return to > from ? std::sqrt(sum / static_cast<double>(to - from)) : 0.0;
}

// The force less its centred moving mean: its content above about 5 Hz.
std::vector<double> highPass(const std::vector<double>& force)
{
  const int n = static_cast<int>(force.size());
  std::vector<double> sums(n + 1, 0.0);
  for (int i = 0; i < n; ++i)
  {
    sums[i + 1] = sums[i] + force[i];
  }
  std::vector<double> high(n);
  for (int i = 0; i < n; ++i)
  {
    const int lo = std::max(0, i - kHighPassHalfWindow);
    const int hi = std::min(n, i + kHighPassHalfWindow + 1);
    high[i] = force[i] - (sums[hi] - sums[lo]) / (hi - lo);
  }
  return high;
}

// The least-squares slope of -force against position over the samples taken (N/m).
double feltStiffness(const Port& port, double from, double to)
{
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < port.rendered.size(); ++i)
  {
    const double t = (static_cast<double>(i) + 1.0) * kTick;
    if (t < from || t > to || !port.pressing[i])
    {
      continue;
    }
    const double x = std::abs(port.positions[i]);
    const double y = std::abs(port.rendered[i]);
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  return n > 10.0 && denominator > 0.0 ? (n * sxy - sx * sy) / denominator : 0.0;
}
}  // namespace

const char* delayTaskName(DelayTask task)
{
  switch (task)
  {
    case DelayTask::kPress:
      return "press";
    case DelayTask::kTap:
      return "tap";
    case DelayTask::kGrasp:
      return "grasp";
    case DelayTask::kFree:
      return "free";
  }
  return "?";
}

const char* delayOperatorName(DelayOperator op)
{
  return op == DelayOperator::kWorstCase ? "worst_case" : "human_like";
}

const char* passivityFormName(PassivityForm form)
{
  return form == PassivityForm::kDevicePort ? "device_port" : "two_port";
}

DelayTrialResult runDelayTrial(const DelayTrial& trial)
{
  const CouplingProfile coupling;
  const OperatorModel hand = operatorModel(trial.op);
  PassivityParams passivity;
  if (!trial.controller)
  {
    passivity.passivity_damping_limit = 0.0;  // the observer only
  }
  PassivityParams observer_only = passivity;
  observer_only.passivity_damping_limit = 0.0;
  // The two-port form acts on forwarded forces only: with the local coupling the link carries
  // positions both ways, and its physics side has no force to answer with (delay_sweep.h).
  const bool two_port = trial.form == PassivityForm::kTwoPort && !trial.local_coupling;
  const int port_count = trial.task == DelayTask::kGrasp ? 2 : 1;
  std::vector<Port> ports;
  ports.reserve(port_count);
  for (int p = 0; p < port_count; ++p)
  {
    DelayLineParams link;
    link.delay = 0.5 * trial.round_trip;
    link.jitter = trial.jitter_fraction * link.delay;
    link.loss = trial.loss;
    link.seed = trial.seed * 4 + 2 * p;
    DelayLineParams back = link;
    back.seed = link.seed + 1;
    ports.emplace_back(link, back, passivity, observer_only, two_port ? passivity : observer_only);
    ports.back().x = ports.back().previous_x = restPoint(trial.task, p, 0.0);
  }
  double block = 0.0;  // m: the grasp block's centre
  double block_v = 0.0;
  const long ticks = std::lround(kDuration / kTick);
  for (long tick = 0; tick < ticks; ++tick)
  {
    const double now = static_cast<double>(tick) * kTick;
    for (Port& port : ports)
    {
      port.up.send(now, port.x, port.v, port.device_port.observer().in());
    }
    // The physics: each port's proxy stops at its surface; the coupling pulls it.
    double on_block = 0.0;
    for (int p = 0; p < port_count; ++p)
    {
      Port& port = ports[p];
      Message arrived{};
      if (port.up.receive(now, &arrived))
      {
        port.seen = arrived;
        port.physics_port.remote().receive({arrived.stamp, arrived.energy});
      }
      double force_on_hand = 0.0;
      bool pressing = false;
      if (port.seen.stamp >= 0.0 && trial.task != DelayTask::kFree)
      {
        const double sign = p == 0 ? 1.0 : -1.0;  // port 0 pushes along +x
        const double surface = trial.task == DelayTask::kGrasp ? block - sign * kBlockHalfWidth : 0.0;
        // The coupling's force on the hand at (x, v): its proxy stops at the surface.
        const auto pull_at = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& v)
        {
          const bool in = sign * (x.x() - surface) > 0.0;
          const double proxy = in ? surface : x.x();
          const double proxy_v = in ? (trial.task == DelayTask::kGrasp ? block_v : 0.0) : v.x();
          return couplingForce(coupling, x, v, Eigen::Vector3d(proxy, 0, 0), Eigen::Vector3d(proxy_v, 0, 0));
        };
        // The hand where the physics takes it: as seen, or as the two-port's physics side moves it.
        Eigen::Vector3d hand_x(port.seen.a, 0, 0);
        Eigen::Vector3d hand_v(port.seen.b, 0, 0);
        CouplingForce pull = pull_at(hand_x, hand_v);
        if (!trial.local_coupling)
        {
          port.physics_port.answer(
              Eigen::Vector3d(port.seen.a, 0, 0), Eigen::Vector3d(port.seen.b, 0, 0),
              [&](const Eigen::Vector3d& x, const Eigen::Vector3d& v) -> Eigen::Vector3d
              { return -pull_at(x, v).on_proxy; },
              &hand_x, &hand_v);
          pull = pull_at(hand_x, hand_v);
          port.max_drift = std::max(port.max_drift, port.physics_port.drift().norm());
        }
        pressing = sign * (hand_x.x() - surface) > 0.0;
        const double proxy = pressing ? surface : hand_x.x();
        force_on_hand = -pull.on_proxy.x();
        if (pressing)
        {
          on_block += pull.on_proxy.x();
        }
        if (trial.local_coupling)
        {
          Message state{0.0, 0.0, proxy, 0.0, 0.0};
          state.target = hand_x.x();
          state.force = force_on_hand;
          state.plane = pressing ? -sign : 0.0;  // out of the wall, toward the hand
          port.down.send(now, state);
        }
      }
      else if (trial.local_coupling && port.seen.stamp >= 0.0)
      {
        // Free space: the god-object is where the hand was seen, no force, no plane.
        Message state{0.0, 0.0, port.seen.a, 0.0, 0.0};
        state.target = port.seen.a;
        port.down.send(now, state);
      }
      if (port.seen.stamp >= 0.0 && !trial.local_coupling && trial.task == DelayTask::kFree)
      {
        Eigen::Vector3d hand_x, hand_v;  // free space: no force, nothing to settle
        port.physics_port.answer(
            Eigen::Vector3d(port.seen.a, 0, 0), Eigen::Vector3d(port.seen.b, 0, 0),
            [](const Eigen::Vector3d&, const Eigen::Vector3d&) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); },
            &hand_x, &hand_v);
      }
      if (!trial.local_coupling)
      {
        port.down.send(now, force_on_hand, 0.0, port.physics_port.observer().in());
      }
      port.pressing.push_back(pressing ? 1 : 0);
    }
    if (trial.task == DelayTask::kGrasp)
    {
      block_v += kTick * on_block / kBlockMass;
      block += kTick * block_v;
    }
    // The devices: the newest force, through the controller; the hands move the handles.
    for (int p = 0; p < port_count; ++p)
    {
      Port& port = ports[p];
      Message arrived{};
      if (port.down.receive(now, &arrived))
      {
        if (trial.local_coupling && port.command.stamp < 0.0)
        {
          // The first: as the haptic node takes it, the anchor on the hand's predicted proxy.
          port.render.anchor = predictedProxy(localStep(arrived), Eigen::Vector3d(port.x, 0, 0));
          port.render.force = Eigen::Vector3d(arrived.force, 0, 0);
        }
        port.command = arrived;
        port.device_port.remote().receive({arrived.stamp, arrived.energy});
      }
      double command = 0.0;
      if (port.command.stamp >= 0.0)
      {
        command = trial.local_coupling ? localCoupling(coupling, port) : port.command.a;
      }
      // Either form's device renders through the one-port controller; the two-port's device side
      // counts what it rendered.
      const Eigen::Vector3d handle_v(port.v, 0, 0);
      const double rendered = port.controller.apply(Eigen::Vector3d(command, 0, 0), handle_v, coupling.max_force).x();
      port.device_port.apply(Eigen::Vector3d(rendered, 0, 0), handle_v, coupling.max_force);
      const double rest =
          restPoint(trial.task, p, now) +
          (now < kDuration - kQuietTail ? hand.tremor * std::sin(2.0 * M_PI * hand.tremor_hz * now) : 0.0) *
              (p == 0 ? 1 : -1);
      const double by_hand = hand.stiffness * (rest - port.x) - hand.damping * port.v;
      port.previous_x = port.x;
      port.previous_v = port.v;
      port.v += kTick * (by_hand + rendered) / hand.mass;
      port.x += kTick * port.v;
      port.rendered.push_back(rendered);
      port.positions.push_back(trial.task == DelayTask::kGrasp ? port.x - (block - (p == 0 ? 1 : -1) * kBlockHalfWidth)
                                                               : port.x);
    }
  }
  DelayTrialResult result;
  result.max_force_N = coupling.max_force;
  result.lowest_energy_J = 0.0;
  for (int p = 0; p < port_count; ++p)
  {
    const Port& port = ports[p];
    result.lowest_energy_J = std::min(result.lowest_energy_J, port.controller.lowestEnergy());
    result.device_margin_J = std::min(result.device_margin_J, port.device_port.lowestMargin());
    result.physics_margin_J = std::min(result.physics_margin_J, port.physics_port.lowestMargin());
    result.max_drift_m = std::max(result.max_drift_m, port.max_drift);
    result.damped_ticks +=
        port.controller.activeTicks() + port.device_port.activeTicks() + port.physics_port.activeTicks();
    result.lost_messages += port.up.lost() + port.down.lost();
    for (const double f : port.rendered)
    {
      result.peak_force_N = std::max(result.peak_force_N, std::abs(f));
    }
    std::size_t first = port.rendered.size();
    for (std::size_t i = 0; i < port.rendered.size(); ++i)
    {
      if (port.rendered[i] != 0.0)
      {
        first = i;
        break;
      }
    }
    if (first < port.rendered.size())
    {
      const std::vector<double> high = highPass(port.rendered);
      const std::size_t n = high.size();
      result.early_hf_rms_N = std::max(result.early_hf_rms_N, rms(high, first, std::min(n, first + 1000)));
      result.late_hf_rms_N = std::max(result.late_hf_rms_N, rms(high, n - 1000, n));
      const std::size_t quiet = n - static_cast<std::size_t>(std::lround(kQuietTail / kTick));
      result.tremor_hf_rms_N = std::max(result.tremor_hf_rms_N, rms(high, quiet - kTremorWindow, quiet));
    }
  }
  // Sustained: the last second's content above 5 Hz (the hand no longer trembling) has not fallen
  // to half the first second's, and is over what the same operator and task give with no link.
  if (trial.round_trip > 0.0 || trial.jitter_fraction > 0.0 || trial.loss > 0.0)
  {
    DelayTrial baseline = trial;
    baseline.round_trip = 0.0;
    baseline.jitter_fraction = 0.0;
    baseline.loss = 0.0;
    baseline.controller = true;
    const DelayTrialResult alone = runDelayTrial(baseline);
    result.baseline_late_hf_rms_N = alone.late_hf_rms_N;
    result.baseline_tremor_hf_rms_N = alone.tremor_hf_rms_N;
  }
  else
  {
    result.baseline_late_hf_rms_N = result.late_hf_rms_N;
    result.baseline_tremor_hf_rms_N = result.tremor_hf_rms_N;
  }
  result.sustained = result.late_hf_rms_N > result.baseline_late_hf_rms_N + kSustainedHfRms &&
                     result.late_hf_rms_N > 0.5 * result.early_hf_rms_N;
  if (trial.task == DelayTask::kPress)
  {
    result.felt_stiffness_N_per_m = feltStiffness(ports[0], 0.5, 2.0);
  }
  else if (trial.task == DelayTask::kGrasp)
  {
    result.felt_stiffness_N_per_m = feltStiffness(ports[0], 0.5, 1.5);
  }
  return result;
}

std::vector<DelayTrial> delaySweep()
{
  std::vector<DelayTrial> trials;
  for (const DelayTask task : {DelayTask::kPress, DelayTask::kTap, DelayTask::kGrasp, DelayTask::kFree})
  {
    for (const DelayOperator op : {DelayOperator::kWorstCase, DelayOperator::kHumanLike})
    {
      for (const double round_trip : {0.0, 0.01, 0.03, 0.06, 0.1})
      {
        for (const double jitter : {0.0, 0.2, 0.5})
        {
          for (const double loss : {0.0, 0.02})
          {
            if (round_trip == 0.0 && (jitter > 0.0 || loss > 0.0))
            {
              continue;  // the baseline: no link at all
            }
            for (const bool controller : {false, true})
            {
              DelayTrial trial;
              trial.task = task;
              trial.op = op;
              trial.round_trip = round_trip;
              trial.jitter_fraction = jitter;
              trial.loss = loss;
              trial.controller = controller;
              trials.push_back(trial);
            }
          }
        }
      }
    }
  }
  // The two-port form, on: every setting again.
  const std::size_t one_port_rows = trials.size();
  for (std::size_t i = 0; i < one_port_rows; ++i)
  {
    if (trials[i].controller)
    {
      DelayTrial trial = trials[i];
      trial.form = PassivityForm::kTwoPort;
      trials.push_back(trial);
    }
  }
  return trials;
}

std::string delayTrialJson(const DelayTrial& trial, const DelayTrialResult& result)
{
  char line[1536];
  std::snprintf(line, sizeof(line),
                "{\"task\": \"%s\", \"operator\": \"%s\", \"round_trip_s\": %.3f, \"jitter_fraction\": %.2f, "
                "\"loss\": %.3f, \"controller\": %s, \"lowest_energy_J\": %.6g, \"early_hf_rms_N\": %.6g, "
                "\"late_hf_rms_N\": %.6g, \"baseline_late_hf_rms_N\": %.6g, \"sustained\": %s, \"peak_force_N\": %.6g, "
                "\"max_force_N\": %.6g, "
                "\"felt_stiffness_N_per_m\": %.6g, \"damped_ticks\": %ld, \"lost_messages\": %ld, "
                "\"tremor_hf_rms_N\": %.6g, \"baseline_tremor_hf_rms_N\": %.6g, \"passivity\": \"%s\", "
                "\"device_margin_J\": %.6g, \"physics_margin_J\": %.6g, \"max_drift_m\": %.6g}",
                delayTaskName(trial.task), delayOperatorName(trial.op), trial.round_trip, trial.jitter_fraction,
                trial.loss, trial.controller ? "true" : "false", result.lowest_energy_J, result.early_hf_rms_N,
                result.late_hf_rms_N, result.baseline_late_hf_rms_N, result.sustained ? "true" : "false",
                result.peak_force_N, result.max_force_N, result.felt_stiffness_N_per_m, result.damped_ticks,
                result.lost_messages, result.tremor_hf_rms_N, result.baseline_tremor_hf_rms_N,
                passivityFormName(trial.form), result.device_margin_J, result.physics_margin_J, result.max_drift_m);
  std::string json = line;
  if (trial.local_coupling)
  {
    json.insert(json.size() - 1, ", \"local_coupling\": true");  // delaySweep()'s rows have none
  }
  return json;
}
}  // namespace god_finger
