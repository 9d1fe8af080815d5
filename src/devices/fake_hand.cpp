#include "god_finger/devices/fake_hand.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/parameter_table.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
namespace
{
constexpr double kClosed = 1.0;      // s
constexpr double kLiftStart = 1.5;   // s
constexpr double kLiftEnd = 3.5;     // s
constexpr double kRelease = 4.5;     // s
constexpr double kOpen = 4.8;        // s
constexpr double kLowered = 5.8;     // s
constexpr double kSpreadDeg = 35.0;  // between neighbouring fingers
constexpr double kTurned = 4.2;      // s: the wrist's turn done
constexpr int kTurnSteps = 8;        // waypoints along the turn's arc (0.06 rad apart at 0.5 rad)

// The wrist's turn (rad) about the grasp's axis at the turn's k-th of kTurnSteps waypoints.
double turnAt(const FakeHandParams& params, int k)
{
  return params.wrist_turn * static_cast<double>(k) / kTurnSteps;
}
double turnTime(int k)
{
  return kLiftEnd + (kTurned - kLiftEnd) * static_cast<double>(k) / kTurnSteps;
}

class FakeHand : public HandSource
{
 public:
  explicit FakeHand(const FakeHandParams& params)
      : names_(fakeHandFingerNames(params.fingers)),
        paths_(fakeHandPaths(params)),
        start_orientations_(fakeHandOrientations(params)),
        orientations_(fakeHandOrientationPaths(params)),
        turning_(params.wrist_turn != 0.0),
        cycle_(params.cycle)
  {
  }
  std::string name() const override
  {
    return "fake_hand";
  }
  std::vector<std::string> fingers() const override
  {
    return names_;
  }
  void setScriptStart(double time) override
  {
    start_ = time;
  }
  void read(double time, std::vector<DeviceReading>* readings) override
  {
    if (std::isnan(start_))
    {
      start_ = time;  // no script start given: the script starts at the first read
    }
    double t = time - start_;
    if (cycle_ > 0.0 && t > 0.0)
    {
      t = std::fmod(t, cycle_);
    }
    const double dt = 1e-3;
    for (std::size_t i = 0; i < paths_.size(); ++i)
    {
      DeviceReading& reading = (*readings)[i];
      reading.position = paths_[i].at(t);
      reading.velocity = (reading.position - paths_[i].at(t - dt)) / dt;
      reading.buttons = 0;
      reading.tracked = true;
      if (!start_orientations_.empty())
      {
        reading.has_orientation = true;
        // Unturned, the orientation as made (a path's would be normalised: a last bit apart).
        reading.orientation = turning_ ? orientations_[i].at(t) : start_orientations_[i];
      }
    }
  }

 private:
  std::vector<std::string> names_;
  std::vector<WaypointPath> paths_;
  std::vector<Eigen::Quaterniond> start_orientations_;
  std::vector<OrientationPath> orientations_;
  bool turning_;
  double start_ = NAN;
  double cycle_;
};
}  // namespace

const ParameterTable<FakeHandParams>& fakeHandParameterTable()
{
  using P = FakeHandParams;
  static const ParameterTable<P> table = {
      integerRow<P>("fingers", closed(2, 4), "fingers besides the thumb (index, middle, ring, little)",
                    [](P& p) -> int& { return p.fingers; }),
      realRow<P>("grasp_radius", "m", openClosed(0.0, 0.5), "the fingers' distance from the mug's axis, closed",
                 [](P& p) -> double& { return p.grasp_radius; }),
      realRow<P>("open_radius", "m", openClosed(0.0, 0.5),
                 "the fingers' distance from the mug's axis, open (> grasp_radius)",
                 [](P& p) -> double& { return p.open_radius; }),
      realRow<P>("object_radius", "m", openClosed(0.0, 0.5),
                 "the grasped object's radius, to balance the thumb against the fingers",
                 [](P& p) -> double& { return p.object_radius; }),
      realRow<P>("lift", "m", closed(0.0, 0.5), "how high the closed hand lifts",
                 [](P& p) -> double& { return p.lift; }),
      realRow<P>("cycle", "s", closed(0.0, 3600.0),
                 "0 grasps once; else grasps again every cycle s (>= 5.8, the grasp's length)",
                 [](P& p) -> double& { return p.cycle; }),
      choiceRow<P>(
          "orientation", "pulp_in, none",
          "pulp_in: oriented (6-DOF) fingertips, pulp towards the axis, tip down; none: positions only (3-DOF)",
          [](const P& p) -> std::string { return p.oriented ? "pulp_in" : "none"; },
          [](P* p, const std::string& text)
          {
            if (text != "pulp_in" && text != "none")
            {
              return false;
            }
            p->oriented = text == "pulp_in";
            return true;
          }),
      realRow<P>("finger_pitch", "rad", closed(0.0, 1.2),
                 "pulp_in: each finger's body leans out from the wall by this (0: along it)",
                 [](P& p) -> double& { return p.finger_pitch; }),
      realRow<P>("wrist_turn", "rad", closed(-1.5, 1.5),
                 "held up, the hand turns about the grasp's axis by this (counter-clockwise from above) and "
                 "back while it lowers (0: no turn)",
                 [](P& p) -> double& { return p.wrist_turn; }),
  };
  return table;
}

FakeHandParams readFakeHandParams(const ParameterSource& source)
{
  FakeHandParams params;
  readRows(source, fakeHandParameterTable(), &params);
  params.grasp_center = readVector(source, "grasp_center", params.grasp_center);
  if (params.cycle > 0.0 && params.cycle < kLowered)
  {
    throw InputError("parameter '" + source.fullName("cycle") + "' (" + formatNumber(params.cycle) +
                     " s) must be 0 (grasp once) or at least the grasp's " + formatNumber(kLowered) + " s");
  }
  if (!(params.open_radius > params.grasp_radius))
  {
    throw InputError("parameter '" + source.fullName("open_radius") + "' (" + formatNumber(params.open_radius) +
                     " m) must exceed '" + source.fullName("grasp_radius") + "' (" + formatNumber(params.grasp_radius) +
                     " m): the hand opens wider than it closes");
  }
  return params;
}

std::vector<std::string> fakeHandFingerNames(int fingers)
{
  static const char* const kNames[] = {"thumb", "index", "middle", "ring", "little"};
  std::vector<std::string> names;
  for (int i = 0; i <= fingers && i < 5; ++i)
  {
    names.push_back(kNames[i]);
  }
  return names;
}

std::vector<WaypointPath> fakeHandPaths(const FakeHandParams& params)
{
  const double pi = std::acos(-1.0);
  const double press = params.object_radius - params.grasp_radius;  // a finger's depth into the wall
  std::vector<double> angles;                                       // the fingers', rad
  double push_y = 0.0;                                              // the fingers' push along -y, in depths
  for (int k = 0; k < params.fingers; ++k)
  {
    const double degrees = 270.0 + kSpreadDeg * (k - 0.5 * (params.fingers - 1));
    angles.push_back(degrees * pi / 180.0);
    push_y += -std::sin(angles.back());
  }
  // The thumb presses as deep as balances the fingers along y.
  const double thumb_closed = std::max(0.0, params.object_radius - press * push_y);
  std::vector<WaypointPath> paths;
  const Eigen::Vector3d up(0.0, 0.0, params.lift);
  auto path = [&](double angle, double closed)
  {
    const Eigen::Vector3d out(std::cos(angle), std::sin(angle), 0.0);
    const Eigen::Vector3d open = params.grasp_center + params.open_radius * out;
    const Eigen::Vector3d shut = params.grasp_center + closed * out;
    if (params.wrist_turn == 0.0)
    {
      return WaypointPath({{0.0, open},
                           {kClosed, shut},
                           {kLiftStart, shut},
                           {kLiftEnd, shut + up},
                           {kRelease, shut + up},
                           {kOpen, open + up},
                           {kLowered, open}});
    }
    // Turned about the axis by `turn`, at `radius` from it.
    const auto turned = [&](double turn, double radius) -> Eigen::Vector3d
    { return params.grasp_center + radius * Eigen::Vector3d(std::cos(angle + turn), std::sin(angle + turn), 0.0); };
    std::vector<Waypoint> waypoints = {{0.0, open}, {kClosed, shut}, {kLiftStart, shut}};
    for (int k = 0; k <= kTurnSteps; ++k)
    {
      waypoints.push_back({turnTime(k), turned(turnAt(params, k), closed) + up});
    }
    waypoints.push_back({kRelease, turned(params.wrist_turn, closed) + up});
    waypoints.push_back({kOpen, turned(params.wrist_turn, params.open_radius) + up});
    for (int k = kTurnSteps - 1; k >= 0; --k)  // down and back along the open arc
    {
      const double fraction = 1.0 - static_cast<double>(k) / kTurnSteps;
      waypoints.push_back({kOpen + (kLowered - kOpen) * fraction,
                           turned(turnAt(params, k), params.open_radius) + (1.0 - fraction) * up});
    }
    return WaypointPath(waypoints);
  };
  paths.push_back(path(0.5 * pi, thumb_closed));
  for (double angle : angles)
  {
    paths.push_back(path(angle, params.grasp_radius));
  }
  return paths;
}

std::vector<Eigen::Quaterniond> fakeHandOrientations(const FakeHandParams& params)
{
  std::vector<Eigen::Quaterniond> orientations;
  if (!params.oriented)
  {
    return orientations;
  }
  const std::vector<WaypointPath> paths = fakeHandPaths(params);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const double lean = params.finger_pitch;
  for (const WaypointPath& path : paths)
  {
    // Out from the axis towards where the finger opens (its script's start), horizontal.
    Eigen::Vector3d out = path.at(0.0) - params.grasp_center;
    out.z() = 0.0;
    out.normalize();
    Eigen::Matrix3d frame;
    frame.col(0) = -std::cos(lean) * up - std::sin(lean) * out;  // the tip: down, the body out
    frame.col(2) = -std::cos(lean) * out + std::sin(lean) * up;  // the pulp: towards the axis
    frame.col(1) = frame.col(2).cross(frame.col(0));
    orientations.emplace_back(frame);
  }
  return orientations;
}

std::vector<OrientationPath> fakeHandOrientationPaths(const FakeHandParams& params)
{
  std::vector<OrientationPath> paths;
  for (const Eigen::Quaterniond& start : fakeHandOrientations(params))
  {
    if (params.wrist_turn == 0.0)
    {
      paths.emplace_back(std::vector<OrientationWaypoint>{{0.0, start}});
      continue;
    }
    const auto turned = [&](double turn) -> Eigen::Quaterniond
    { return Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ())) * start; };
    std::vector<OrientationWaypoint> waypoints = {{kLiftEnd, start}};
    for (int k = 1; k <= kTurnSteps; ++k)
    {
      waypoints.push_back({turnTime(k), turned(turnAt(params, k))});
    }
    waypoints.push_back({kOpen, turned(params.wrist_turn)});
    waypoints.push_back({kLowered, start});
    paths.emplace_back(waypoints);
  }
  return paths;
}

std::shared_ptr<HandSource> makeFakeHand(const FakeHandParams& params)
{
  return std::make_shared<FakeHand>(params);
}
}  // namespace god_finger
