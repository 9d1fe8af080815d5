#include "node_parameters.h"

#include "parameters.h"

namespace god_finger
{
const ParameterTable<NodeParams>& nodeParameterTable()
{
  using P = NodeParams;
  static const ParameterTable<P> table = {
      realRow<P>("publish_rate", "Hz", closed(1.0, 1000.0),
                 "rate of the markers, bodies' TF, contact areas and diagnostics",
                 [](P& p) -> double& { return p.publish_rate; }),
      realRow<P>("script_delay", "s", closed(0.0, 60.0), "simulated devices start their scripts this long after launch",
                 [](P& p) -> double& { return p.script_delay; }),
      realRow<P>("proxy_timeout", "s", openClosed(0.0, 10.0),
                 "the haptic node stops rendering a proxy older than this (the driver's watchdog then ramps down)",
                 [](P& p) -> double& { return p.proxy_timeout; }),
      integerRow<P>("wait_for_subscribers", closed(0, 100),
                    "sim_time: the servo waits for this many subscribers of each device/state",
                    [](P& p) -> int& { return p.wait_for_subscribers; }),
  };
  return table;
}

NodeParams readNodeParams(const ros::NodeHandle& pnh)
{
  NodeParams params;
  readRows(RosParameterSource(pnh), nodeParameterTable(), &params);
  return params;
}

ServoLoopParams readLoopParams(const ros::NodeHandle& pnh)
{
  ServoLoopParams params;
  readRows(RosParameterSource(pnh), servoLoopParameterTable(), &params);
  return params;
}
}  // namespace god_finger
