// The delay line's schedule (runtime/delay_line.h), on its own: nothing set, a message leaves
// when it entered; a set delay is exact; jitter spreads the delays as a Gaussian of that
// standard deviation (over 20,000 messages) and, first in first out, never reorders them; loss
// drops its share; the same seed repeats the schedule bit for bit, another seed does not; a
// setting one changes leaves the other settings' draws alone; bad settings are refused in one
// line.
#include "god_finger/runtime/delay_line.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace god_finger
{
namespace
{
constexpr int kMessages = 20000;  // at 1 kHz: 20 s of a haptic link

std::vector<double> schedule(const DelayLineParams& params)
{
  DelaySchedule line(params);
  std::vector<double> leaves;
  for (int i = 0; i < kMessages; ++i)
  {
    leaves.push_back(line.release(1e-3 * i));
  }
  return leaves;
}

TEST(DelayLine, NothingSetLeavesAtOnceAndADelayIsExact)
{
  const std::vector<double> none = schedule(DelayLineParams());
  DelayLineParams delayed;
  delayed.delay = 0.03;
  const std::vector<double> late = schedule(delayed);
  for (int i = 0; i < kMessages; ++i)
  {
    ASSERT_EQ(none[i], 1e-3 * i);
    ASSERT_EQ(late[i], 1e-3 * i + 0.03);
  }
}

TEST(DelayLine, JitterSpreadsTheDelaysAsAGaussianAndFirstInFirstOutKeepsTheOrder)
{
  DelayLineParams params;
  params.delay = 0.03;
  params.jitter = 0.005;
  params.reorder = 1;
  const std::vector<double> free_order = schedule(params);
  double sum = 0.0;
  double squares = 0.0;
  int overtaken = 0;
  for (int i = 0; i < kMessages; ++i)
  {
    const double delay = free_order[i] - 1e-3 * i;
    ASSERT_GE(delay, 0.0);
    sum += delay;
    squares += delay * delay;
    overtaken += i > 0 && free_order[i] < free_order[i - 1] ? 1 : 0;
  }
  const double mean = sum / kMessages;
  const double deviation = std::sqrt(squares / kMessages - mean * mean);
  std::printf("[ measured ] jitter 5 ms over 30 ms: mean %.5f s, standard deviation %.5f s, %d overtakes\n", mean,
              deviation, overtaken);
  // 20,000 draws: the mean within 4 standard errors (0.14 ms), the deviation within 3 %.
  EXPECT_NEAR(mean, 0.03, 4.0 * 0.005 / std::sqrt(double(kMessages)));
  EXPECT_NEAR(deviation, 0.005, 0.03 * 0.005);
  EXPECT_GT(overtaken, 1000);  // 5 ms of spread at 1 ms spacing: many overtake
  params.reorder = 0;
  const std::vector<double> in_order = schedule(params);
  for (int i = 1; i < kMessages; ++i)
  {
    ASSERT_GE(in_order[i], in_order[i - 1]);
    ASSERT_GE(in_order[i], free_order[i]);  // held back only, never sooner
  }
}

TEST(DelayLine, LossDropsItsShareAndASeedRepeatsTheSchedule)
{
  DelayLineParams params;
  params.delay = 0.01;
  params.jitter = 0.002;
  params.loss = 0.02;
  params.seed = 7;
  DelaySchedule line(params);
  for (int i = 0; i < kMessages; ++i)
  {
    line.release(1e-3 * i);
  }
  const double share = double(line.lost()) / line.entered();
  std::printf("[ measured ] loss 2 %%: %ld of %ld lost (%.4f)\n", line.lost(), line.entered(), share);
  // Binomial: the standard error of the share is 0.001; within 4.
  EXPECT_NEAR(share, 0.02, 0.004);
  EXPECT_EQ(schedule(params), schedule(params));
  DelayLineParams other = params;
  other.seed = 8;
  EXPECT_NE(schedule(params), schedule(other));
  // Loss changes which messages are lost, not when the others leave (when they may overtake:
  // first in first out, a lost message no longer holds back the ones after it).
  DelayLineParams lossy = params;
  lossy.reorder = 1;
  DelayLineParams lossless = lossy;
  lossless.loss = 0.0;
  const std::vector<double> with_loss = schedule(lossy);
  const std::vector<double> without = schedule(lossless);
  for (int i = 0; i < kMessages; ++i)
  {
    if (with_loss[i] >= 0.0)
    {
      ASSERT_EQ(with_loss[i], without[i]);
    }
  }
}

TEST(DelayLine, BadSettingsAreRefusedInOneLine)
{
  DelayLineParams params;
  params.delay = -0.01;
  EXPECT_THROW(DelaySchedule{params}, InputError);
  EXPECT_NE(validate(params).find("delay"), std::string::npos) << validate(params);
  params = DelayLineParams();
  params.loss = 1.5;
  EXPECT_NE(validate(params).find("loss"), std::string::npos) << validate(params);
  params = DelayLineParams();
  params.jitter = std::nan("");
  EXPECT_NE(validate(params).find("jitter"), std::string::npos) << validate(params);
  params = DelayLineParams();
  params.reorder = 2;
  EXPECT_NE(validate(params).find("reorder"), std::string::npos) << validate(params);
}
}  // namespace
}  // namespace god_finger
