// Simulated time's physics and its test seam on their own (src/runtime/physics_delay_seam.h):
// each tick's targets are stepped within the tick; a step made d periods late completes d ticks
// later, the targets posted meanwhile are skipped, and that tick's own targets are stepped after
// it; the delay is asked once per step taken.
#include "physics_delay_seam.h"

#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <vector>

namespace god_finger::internal
{
namespace
{
const std::string kScene = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf";

// A physics side over the ball scene, one finger held above the ball, and its mailboxes.
class Lockstep : public ::testing::Test
{
 protected:
  Lockstep()
      : physics_(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams()), simulated(), 1, &counters_,
                 &commands_, &snapshots_, running_)
  {
    const Eigen::Vector3d start(0.0, 0.0, 0.1);
    physics_.addInterface("finger", start, DeviceProfile().coupling);
    physics_.prepare();
    frame_.targets = {start};
    frame_.velocities = {Eigen::Vector3d::Zero()};
    frame_.let_go = {0};
    frame_.orientations = {Eigen::Quaterniond::Identity()};
    frame_.oriented = {0};
    StepResult start_result;
    start_result.proxies.resize(1);
    mail_ = std::make_unique<ServoMailboxes>(frame_, start_result);
  }

  static ServoLoopParams simulated()
  {
    ServoLoopParams params;
    params.simulated_time = true;
    return params;
  }

  // Tick k: its targets posted, the seam's physics; the tick of the newest result, -1 for none.
  long tick(PhysicsDelaySeam* seam, long k)
  {
    frame_.tick = k;
    frame_.time = 1e-3 * static_cast<double>(k);
    mail_->targets.back() = frame_;
    mail_->targets.publish();
    seam->tick(&physics_, mail_.get());
    WorldSnapshot snapshot;
    while (snapshots_.tryPop(&snapshot))
    {
    }
    return mail_->results.take() ? mail_->results.front().tick : -1;
  }

  ServoCounters counters_;
  SpscQueue<ServoCommand> commands_{4};
  SpscQueue<WorldSnapshot> snapshots_{4};
  const std::atomic<bool> running_{false};
  PhysicsSide physics_;
  TargetFrame frame_;
  std::unique_ptr<ServoMailboxes> mail_;
};

TEST_F(Lockstep, ALateStepCompletesWholePeriodsLaterAndTheTargetsMeanwhileAreSkipped)
{
  std::vector<long> asked;
  PhysicsDelaySeam seam(
      [&asked](long tick)
      {
        asked.push_back(tick);
        return tick == 3 ? 2 : 0;
      },
      frame_);
  std::vector<long> results;
  for (long k = 0; k < 8; ++k)
  {
    results.push_back(tick(&seam, k));
  }
  // Tick 3's step is two periods late: no result at ticks 3 and 4, tick 4's targets skipped; at
  // tick 5 it completes, then tick 5's step, whose result is the newest.
  EXPECT_EQ(results, (std::vector<long>{0, 1, 2, -1, -1, 5, 6, 7}));
  EXPECT_EQ(asked, (std::vector<long>{0, 1, 2, 3, 5, 6, 7}));
  EXPECT_EQ(counters_.physics_steps.load(), 7);
  EXPECT_EQ(counters_.skipped_targets.load(), 1);
  EXPECT_EQ(physics_.world().steps(), 7);
}

TEST_F(Lockstep, WithoutADelayEveryTickIsSteppedInItsTick)
{
  PhysicsDelaySeam seam({}, frame_);
  for (long k = 0; k < 20; ++k)
  {
    ASSERT_EQ(tick(&seam, k), k);
    EXPECT_TRUE(mail_->results.front().proxies[0].proxy_position.allFinite());
  }
  EXPECT_EQ(counters_.skipped_targets.load(), 0);
  EXPECT_EQ(physics_.world().steps(), 20);
}
}  // namespace
}  // namespace god_finger::internal
