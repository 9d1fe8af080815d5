// The soft block under a pad and under a point against the elastic solution (issue 28, item 4):
// the material is exact (a plate's uniform compression), the pad's sink converges toward
// Boussinesq's w0 as the mesh is refined, the point load's grows without bound.
#include "god_finger/scenarios/soft_press_fidelity.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
// The pad's sink target (%) at the finest mesh within 1 kHz: bench/targets.yaml's soft.pad_sink,
// the one place it is written.
double padSinkGoalPercent()
{
  for (const YAML::Node& target : YAML::LoadFile(std::string(GOD_FINGER_SOURCE_DIR) + "/bench/targets.yaml"))
  {
    if (target["id"].as<std::string>() == "soft.pad_sink")
    {
      return target["goal"].as<double>();
    }
  }
  ADD_FAILURE() << "bench/targets.yaml has no target soft.pad_sink";
  return 0.0;
}

TEST(SoftPressFidelity, ThePadConvergesTowardBoussinesqAndThePointDoesNot)
{
  std::vector<SoftPressResult> results;
  for (int nodes : {216, 1000, 2744})
  {
    SoftPressSetup setup;
    setup.nodes = nodes;
    setup.grading = 3.0;
    results.push_back(pressSoftBlock(setup));
    const SoftPressResult& result = results.back();
    std::printf("%s\n", softPressJson(setup, result).c_str());
    EXPECT_EQ(result.nodes, nodes);
    // The material: linear tetrahedra compress uniformly exactly.
    EXPECT_NEAR(result.plate_shortening, result.plate_expected, 1e-9 * result.plate_expected);
    // The pad's area on the mesh is pi a^2 up to its quadrature along the rim.
    EXPECT_NEAR(result.covered_area, M_PI * 1e-4, 0.02 * M_PI * 1e-4);
    EXPECT_NEAR(result.boussinesq, 2.0 * (1.0 - 0.45 * 0.45) * (1.0 / (M_PI * 1e-4)) * 0.01 / 50e3, 1e-15);
  }
  const auto ratio = [&](std::size_t i, bool pad)
  { return (pad ? results[i].pad_centre : results[i].point_centre) / results[i].boussinesq; };
  // The pad: below w0 (a stiff discretisation of a finite block), rising, each refinement adding
  // less than half what the one before added; within the target (soft.pad_sink, 15 %) of w0 at
  // 1,000 nodes (the finest of these whose step fits the 1 kHz budget, bench/REPORT.md section
  // 12; constant-strain tetrahedra missed it by locking, at 0.76) and 10 % at 2,744.
  EXPECT_LT(ratio(0, true), ratio(1, true));
  EXPECT_LT(ratio(1, true), ratio(2, true));
  EXPECT_LT(ratio(2, true), 1.0);
  EXPECT_LT(ratio(2, true) - ratio(1, true), 0.5 * (ratio(1, true) - ratio(0, true)));
  EXPECT_GT(ratio(1, true), 1.0 - padSinkGoalPercent() / 100.0);
  EXPECT_GT(ratio(2, true), 0.90);
  // The point: past w0 already at 1,000 nodes and still growing by more than 0.8 of its last
  // step (a point load's sink has no limit).
  EXPECT_GT(ratio(1, false), 2.0);
  EXPECT_GT(ratio(2, false) - ratio(1, false), 0.8 * (ratio(1, false) - ratio(0, false)));
}
}  // namespace
}  // namespace god_finger
